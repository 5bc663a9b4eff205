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

#ifndef BT_SHOCK_PROPAGATION_FELT_SHARES_H
#define BT_SHOCK_PROPAGATION_FELT_SHARES_H

#include "BulletCollision/NarrowPhaseCollision/btManifoldPoint.h"

/// Who solved a contact point last (private to the plugin; docs/design.md, section 6).
///
/// The felt share F of a point's step impulse T is what both of its bodies received. A group
/// without stacks is Bullet's own solve, every impulse felt by both bodies: F = T, and its next
/// step warm starts from T as stock's does. The converging step delivers every impulse to both
/// bodies too, but starts its rows from zero: it marks its points with F != T (1 where T is 0,
/// else 0), and Bullet's solve of a group that has come apart starts such a point from zero instead
/// of from a stacked group's load that no longer balances. F is kept between steps in
/// btManifoldPoint::m_prevRHS, which Bullet's rigid-body solvers never read (its multibody solver
/// does; that world is not supported).
struct btFeltShares
{
	static btScalar feltShare(const btManifoldPoint& cp) { return cp.m_prevRHS; }
	static void setFeltShare(btManifoldPoint& cp, btScalar felt) { cp.m_prevRHS = felt; }
};

#endif  // BT_SHOCK_PROPAGATION_FELT_SHARES_H
