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

#ifndef BT_SHOCK_PROPAGATION_BOX_FACE_CORNERS_H
#define BT_SHOCK_PROPAGATION_BOX_FACE_CORNERS_H

#include "LinearMath/btScalar.h"

class btPersistentManifold;

/// D30 (docs/design.md, section 11): a box face that rests on another box keeps its corners.
///
/// Bullet's box-box test (btBoxBoxDetector, dBoxBox2) clips the incident face against the
/// reference face and keeps only the points that penetrate. A resting face sits at a depth of a
/// few micrometres, so a corner is reported or not by rounding; while the pair's old points persist
/// the manifold stays whole, but once a box slides farther per step than the manifold's breaking
/// threshold every point is new every step, and on about every other step one or two corners are
/// missing: the box pivots on one edge and what rests on it is thrown off.
///
/// For a manifold between two btBoxShape bodies that holds 1 to 3 points along a face normal,
/// each corner of either box's face towards the other that lies over the other face, at most
/// `reach` metres from it outside or the manifold's breaking threshold inside, is added as a
/// point, unless a point of the manifold is already there (within its breaking threshold).
/// Corners inside are added too: under the pushed stack, sliding at 0.92 m/s, the ground pair's
/// manifold held only the two leading corners while all four were 1-29 micrometres deep at
/// collision time (whether the test or the manifold's cache dropped them was not traced). Every field but geometry and impulses is copied from the manifold's first point
/// (combined friction, restitution, the pair's flags), and gContactAddedCallback is called for it
/// where either body asks for it (CF_CUSTOM_MATERIAL_CALLBACK), as btManifoldResult does. A point
/// at a positive distance is speculative for Bullet's row setup: it pushes only if the bodies
/// close faster than distance / dt. Returns the number of points added.
int btKeepBoxFaceCorners(btPersistentManifold& manifold, btScalar reach);

#endif  // BT_SHOCK_PROPAGATION_BOX_FACE_CORNERS_H
