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

#ifndef BT_SHOCK_PROPAGATION_SUPPORT_BLOCK_H
#define BT_SHOCK_PROPAGATION_SUPPORT_BLOCK_H

#include "btCholesky6.h"
#include "btLoadTransfer.h"

/// The support block solve of the layer passes (D19; private to the plugin).
///
/// While a layer is swept, the rows between a free body and its fixated (or static) supports
/// act on the free body alone: they form one small block, a body of 6 degrees of freedom
/// against its contact rows. Projected Gauss-Seidel solves it row by row and converges at rho^N;
/// a resting body needs all N sweeps to lose what the global pass left. Here, before the
/// layer's sweeps, each free body's block is solved in one step: with e the rows' velocity
/// errors as Bullet's kernels see them and J the rows' Jacobians on the body, the smallest
/// impulse changes d with J W J^T d = e (least squares):
///
///   d = J A^-1 M A^-1 J^T e,   A = J^T J,
///
/// the least-squares velocity change A^-1 J^T e, the momentum M it takes, spread over the rows
/// with the smallest sum of squares. Exact when J has full rank (6), which needs at least three
/// non-collinear points with their friction rows; bodies with fewer keep PGS alone.
///
/// Only a resting block: rows whose contact already carries impulse (warm started or swept),
/// with their friction rows. A new contact (an impact) is PGS's. The result is projected onto
/// each row's limits (normals push, friction within its normal's bound), and kept only if it
/// lowers the rows' quadratic objective 1/2 d^T J W J^T d - d . e (the one each PGS row step
/// lowers): a projected step that does not is discarded, so the block never adds energy a PGS
/// sweep would not.
///
/// D24: given factorOut, the factor of A is kept for the weight pass's load transfer of the same
/// body and rows (btLoadTransfer.h): *factorValid is 1 when the block factored A and every row took
/// part (the transfer's rows), else 0.
///
/// Returns whether the block was solved (the rows' impulses and the body's velocity changed).
bool btSolveSupportBlock(btSolverBody& body, const btAlignedObjectArray<btSolverBody>& bodies, const btLoadTransferRow* rows, int numRows,
						 const btConstraintArray& contacts, btCholesky6* factorOut = 0, char* factorValid = 0);

#endif  // BT_SHOCK_PROPAGATION_SUPPORT_BLOCK_H
