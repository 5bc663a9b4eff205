/*
BulletShockPropagation - velocity-based shock propagation for Bullet
Copyright (c) 2026 the BulletShockPropagation authors

This software is provided 'as-is', without any express or implied warranty.
In no event will the authors be held liable for any damages arising from the use of this software.
Permission is granted to anyone to use this software for any purpose,
including commercial applications, and to alter it and redistribute it freely,
subject to the following restrictions:
1. The origin of this software must not be misrepresented; you must not claim that you wrote the original software. If you use this software in a product, an acknowledgment in the product documentation would be appreciated but is not required.
2. Altered source versions must be plainly marked as such, and must not be misrepresented as being the original software.
3. This notice may not be removed or altered from any source distribution.
*/

#ifndef BT_SHOCK_PROPAGATION_CONTACT_PATCH_H
#define BT_SHOCK_PROPAGATION_CONTACT_PATCH_H

#include "LinearMath/btScalar.h"

class btPersistentManifold;

/// D33 (docs/design.md, section 11): a convex face resting on another face gets its whole patch.
///
/// Bullet's GJK/EPA finds one point per pair and step, and the manifold collects them over steps;
/// a cylinder, hull or capsule that starts resting (or whose points were replaced) stands on one
/// or two points for several steps and pivots: a column of 10 cylinders on the plugin's solve
/// moved 2-15 cm where the converged reference moves 3 mm. btBoxBoxDetector clips whole faces
/// (boxes: D30, btBoxFaceCorners.h); other pairs have no such test, so the patch is completed from
/// the shapes' own support functions, for any convex shape:
///
///   rim_X(k) = S_X(d_k) - m_X s_X n,   d_k = -s_X n + 0.5 (cos(k pi/4) t1 + sin(k pi/4) t2),  k = 0..7
///
/// n is the manifold's normal (from B into A), s_A = 1, s_B = -1, t1 and t2 span the tangent
/// plane, S_X is X's support mapping without its margin m_X (the margin Bullet's GJK rounds the
/// shape by; 0 for a hull with polyhedral features, whose clipping uses the bare faces). Every
/// rim point of X lies on the flat face of X that looks along -s_X n, a corner of it for a
/// polygon, a point of its circle for a cylinder, an end of a capsule's line, or (a sphere) all
/// the same point. A rim point of A is a contact point where it lies within `reach` outside or
/// the manifold's breaking threshold inside the plane through the manifold's first point on B
/// (normal n), and over B's face: inside the polygon of B's rim points in the tangent plane (B a
/// btStaticPlaneShape: everywhere); the same for B's rim against A. Of the candidates, the ones
/// farthest from the points already there (and from each other) are added, up to the manifold's
/// four. Pairs of two btBoxShape bodies are left to D30 (btBoxBoxDetector's boxes have no
/// rounding; its corners are exact). Meshes, heightfields and compounds are not completed (their
/// faces are not one shape's). Every new point copies the manifold's first point (coefficients,
/// flags) and gContactAddedCallback is called for it where a body asks (as btManifoldResult does).
/// Returns the number of points added.
int btCompleteContactPatch(btPersistentManifold& manifold, btScalar reach);

#endif  // BT_SHOCK_PROPAGATION_CONTACT_PATCH_H
