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

#ifndef BT_SHOCK_PROPAGATION_TIPPING_COMPOSITE_H
#define BT_SHOCK_PROPAGATION_TIPPING_COMPOSITE_H

#include "btLoadTransfer.h"

/// D25: a body that tips carries what rests on it. Private to the plugin.
///
/// The weight pass hands a layer's free bodies the loads fixation withheld from them, top-down.
/// Where statics says a body B must tip (its weight and the loads resting on it act outside the
/// convex hull of its support points), the bodies above have already been settled as if B were
/// immovable, so the load B receives is their weight, not their inertia: B alone is driven by the
/// weight of everything above it, and turns far faster than the sub-stack it carries (or, with the
/// guard, is held up). A sub-stack that tips over an edge turns as one rigid body at first.
///
/// So B and the bodies resting on it (members: B first) are merged into one rigid body of their
/// total mass M, centre of mass X and inertia I about X, moving with their total momentum P and
/// angular momentum L about X (V = P / M, Omega = I^-1 L: an inelastic merge; momentum is kept,
/// kinetic energy can only fall, and the impulses between members cancel). B's rows against its
/// support (fixated or static) are then swept for that rigid body, projected Gauss-Seidel with
/// each row's Jacobian taken about X: linear n, angular (p - X) x n = r_B x n + (x_B - X) x n, the
/// rows' own errors, limits and friction bounds, until no row's velocity changes by more than
/// convergedSpeed (m/s) or maxSweeps. Every member then moves with the rigid motion,
/// v_i = V + Omega x (x_i - X), w_i = Omega.
///
/// Against an immovable support each row step lowers the rows' PGS objective and the merged
/// body's kinetic energy (its free motion includes this step's gravity). A fixated support that
/// moves into it can add energy: fixation lets a light support push with the base's own mass to
/// resist (D14), not the composite's. So the solve is kept only if the merged body's kinetic
/// energy did not grow; else the rows are restored and false is returned.
///
/// freeMotionBound (D29): the solve is kept as well if the merged body ends with no more kinetic
/// energy than its motion without the rows' impulses: a row that lets go of an impulse it held
/// (friction whose normal now carries less) gives back energy the merged state had lost to it.
///
/// Members must be dynamic, with linear and angular factors 1 and an invertible inertia, and the
/// base at most btTippingCompositeMaxRows rows; returns false (nothing changed) otherwise.
/// sweepsRun: the sweeps made. Measured (docs/design.md, D25): a column of 6 cubes tipping over a
/// ledge turns at 0.0670 rad/s after 0.2 s where rigid-body dynamics gives 0.0647 (stock SI at 10
/// iterations 0.249, the plugin without the composite 0).
const int btTippingCompositeMaxRows = 64;

bool btSolveTippingComposite(btAlignedObjectArray<btSolverBody>& bodies, const int* members, int numMembers, const btLoadTransferRow* rows,
							 int numRows, const btConstraintArray& contacts, int maxSweeps, btScalar convergedSpeed, int* sweepsRun,
							 bool freeMotionBound = false);

#endif  // BT_SHOCK_PROPAGATION_TIPPING_COMPOSITE_H
