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

#include "BulletCollision/NarrowPhaseCollision/btManifoldPoint.h"

class btCollisionObject;
class btPersistentManifold;

/// A contact point the plugin adds to a manifold (D30, D33): `reference`'s combined coefficients,
/// flags and part ids, at onA / onB with `distance` along `normal` (from B into A), no impulse and no
/// user data; gContactAddedCallback is called for it where either body asks for it
/// (CF_CUSTOM_MATERIAL_CALLBACK), as btManifoldResult does.
btManifoldPoint btAddedContactPoint(const btManifoldPoint& reference, const btCollisionObject* objectA, const btCollisionObject* objectB,
									const btVector3& onA, const btVector3& onB, btScalar distance, const btVector3& normal);

/// D33 (docs/design.md, section 11): a convex face resting on another face gets its whole patch.
///
/// Bullet's GJK/EPA finds one point per pair and step, and when the manifold is full keeps the new
/// point in place of the one leaving the largest area: columns of cylinders ended on three rim
/// points and an inner one, a triangle through their own centre, and fell. btBoxBoxDetector clips
/// whole faces (two boxes: D30, btBoxFaceCorners.h); for every other pair the patch is completed
/// from the parts' own support functions (a part: the body's shape or, for a compound, the child
/// the manifold's points name):
///
///   rim_X(k) = S_X(d_k) - m_X s_X n,   d_k = -s_X n + 0.5 (cos(k pi/4) t1 + sin(k pi/4) t2),  k = 0..7
///
/// n is the manifold's normal (from B into A), s_A = 1, s_B = -1, t1 and t2 span the tangent
/// plane, S_X is X's support mapping without its margin m_X (the margin Bullet's GJK rounds the
/// shape by; 0 for a hull with polyhedral features, whose clipping uses the bare faces). A rim is
/// a face when its points lie in one plane (within 1e-3 of the breaking threshold): a polygon's
/// corners, points of a cylinder's circle; a capsule's rim is its line's two ends, a sphere's one
/// point. For a manifold whose points are all within the breaking threshold (a resting patch):
/// 1. a static part's face (or a btStaticPlaneShape) within about 8 degrees of n gives every point
///    its normal (else the larger face; compared as vectors: in float a dot product rounds to 1 below
///    2.4e-4 rad, and a capsule on a box rolled off under a 5.7e-5 rad tilt); on a static mesh or
///    heightfield each point takes the normal of the triangle under it (processAllTriangles) where
///    the convex face lies along it;
/// 2. a part that is no face touches on its touching segment, the rim points within the breaking
///    threshold of its nearest and where its rim's edges rise through that level (a capsule on its
///    side: its line; a sphere or a corner: one point): every point on it within that level goes
///    back onto the segment (a point Bullet keeps is fixed in the part and lags beside the line
///    once it rolls), at its distance to the face there, and points on one spot merge;
/// 3. candidates: rim points of either part's face, a touching segment's ends, and where an edge of
///    one face's rim crosses an edge of the other's (two planks crossing), within `reach` outside
///    or the breaking threshold inside the other part's face and over it (inside its rim polygon;
///    on a plane everywhere; on a mesh or heightfield over a triangle that faces it); while the
///    manifold holds fewer than four points the candidate farthest from them is added;
/// 4. a full manifold trades a point for a candidate while that enlarges the points' hull by 1%,
///    never its deepest point nor one deeper than `keepDepth` (m; the correction's slop), through
///    removeContactPoint and addManifoldPoint (the app's callbacks run).
/// Every new point copies the manifold's first point (coefficients, flags) and
/// gContactAddedCallback is called for it where a body asks (as btManifoldResult does). Returns
/// the number of points added or traded.
int btCompleteContactPatch(btPersistentManifold& manifold, btScalar reach, btScalar keepDepth);

#endif  // BT_SHOCK_PROPAGATION_CONTACT_PATCH_H
