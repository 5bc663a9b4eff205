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

#ifndef BT_SHOCK_PROPAGATION_LOAD_TRANSFER_H
#define BT_SHOCK_PROPAGATION_LOAD_TRANSFER_H

#include "BulletDynamics/ConstraintSolver/btSolverBody.h"
#include "BulletDynamics/ConstraintSolver/btSolverConstraint.h"
#include "LinearMath/btAlignedObjectArray.h"

struct btCholesky6;

/// Load transfer of the downward pass (D16; private to the plugin).
///
/// A body whose supports are fixated receives the impulse its loads pressed on it: a change of
/// its velocity, delta = (dv, dw). Its support rows must take that load on to the bodies below.
/// Projected Gauss-Seidel does it row by row and leaves a share rho^N of it after N sweeps; a
/// load passed down through K layers leaves about rho^N K^2 of the weight above as velocity,
/// which the next step hands down again (measured: a pyramid of base 12 diverges at 10 sweeps,
/// base 30 needs 60). Here the body's support rows take it in one step, the way a statics
/// solution of the body alone would: the smallest change of their impulses d_lambda (least
/// squares) with sum_i d_lambda_i W J_i^T = -delta, where W J_i^T is row i's velocity change per
/// unit impulse on this body. The change is then projected onto each row's limits (contact
/// normals push, friction within the cone), so what the contacts cannot carry (a load past the
/// support's edge, a push beyond friction) stays as motion: the sweeps that follow resolve it,
/// and the body tips or slides. 6 x 6 normal equations per body, O(rows) per body.
struct btLoadTransferRow
{
	btSolverConstraint* m_row;
	bool m_sideA;  ///< the body is side A of the row
	bool m_contact;  ///< contact normal (else friction, bounded by its contact row)
	int m_position = -1;  ///< btLayeredPasses: the row's place among its layer's contact (or friction) rows
	/// The row's contact point carried impulse last step (its btManifoldPoint::m_appliedImpulse > 0
	/// as the step began). btLayeredPasses reads the points once, in row order, so the support block
	/// does not reach into the manifolds body by body.
	bool m_carried = false;
};

/// A row's Jacobian on the body it transfers to (J_b) and on its other end (J_o).
struct btRowSides
{
	const btVector3& m_linear;
	const btVector3& m_angular;
	const btVector3& m_otherLinear;
	const btVector3& m_otherAngular;
};

inline btRowSides btSidesOf(const btLoadTransferRow& r)
{
	const btSolverConstraint& c = *r.m_row;
	return r.m_sideA ? btRowSides{c.m_contactNormal1, c.m_relpos1CrossNormal, c.m_contactNormal2, c.m_relpos2CrossNormal}
					 : btRowSides{c.m_contactNormal2, c.m_relpos2CrossNormal, c.m_contactNormal1, c.m_relpos1CrossNormal};
}

/// What one more call of Bullet's row kernel would change the row's velocity by, before clamping
/// (m/s): its target (rhs, cfm) less the velocity its ends give it now, `self` being the body the
/// row acts on here and `other` its other end as the row sees it (fixation folds a fixated end's
/// hidden motion into the rhs).
inline btScalar btSupportRowError(const btLoadTransferRow& r, btSolverBody& self, btSolverBody& other)
{
	const btSolverConstraint& c = *r.m_row;
	const btRowSides s = btSidesOf(r);
	return (c.m_rhs - c.m_appliedImpulse * c.m_cfm) / c.m_jacDiagABInv - s.m_otherLinear.dot(other.internalGetDeltaLinearVelocity()) -
		   s.m_otherAngular.dot(other.internalGetDeltaAngularVelocity()) - s.m_linear.dot(self.internalGetDeltaLinearVelocity()) -
		   s.m_angular.dot(self.internalGetDeltaAngularVelocity());
}

/// A friction row's Coulomb bound: its coefficient times its contact row's normal impulse (none
/// pushing, or no contact row: 0).
inline btScalar btFrictionBound(const btSolverConstraint& friction, const btConstraintArray& contacts)
{
	const int contact = friction.m_frictionIndex;
	const btScalar normal = (contact >= 0 && contact < contacts.size()) ? btScalar(contacts[contact].m_appliedImpulse) : btScalar(0);
	return friction.m_friction * btMax(btScalar(0), normal);
}

/// The momentum (linear, angular) M u of a velocity change u = (linear, angular) of a body with
/// inverse mass invMass and world inverse inertia invInertia.
inline void btMomentumOf(btScalar invMass, const btMatrix3x3& invInertia, const btVector3& linear, const btVector3& angular, btScalar out[6])
{
	const btVector3 p = linear / invMass;
	const btVector3 l = invInertia.inverse() * angular;
	for (int a = 0; a < 3; ++a)
	{
		out[a] = p[a];
		out[3 + a] = l[a];
	}
}

/// Undo the velocity change of `body` since its solver deltas were (beforeLinear, beforeAngular)
/// through `rows` (see above), whose other ends are immovable while this runs. contacts: the
/// step's contact pool (friction rows find their normal impulse through m_frictionIndex).
/// Returns the total impulse magnitude moved onto the rows.
btScalar btTransferLoad(btSolverBody& body, const btVector3& beforeLinear, const btVector3& beforeAngular,
						const btLoadTransferRow* rows, int numRows, const btConstraintArray& contacts);

/// D24: the same transfer solved with the factor of A = J^T J the body's support block made of the
/// same rows this step (btSupportBlock.h; J the rows' Jacobians on the body, M = W^-1 its mass and
/// inertia). Since H = W J^T, H H^T = W A W and the least-norm change is d_lambda = J A^-1 M target:
/// one solve with that factor instead of forming and factoring H H^T. Without the shift above, which
/// only keeps that factorisation defined where the rows cannot reach; the block factors A only
/// where they reach every direction (its pivot test). The projection is the one above.
btScalar btTransferLoad(btSolverBody& body, const btVector3& beforeLinear, const btVector3& beforeAngular,
						const btLoadTransferRow* rows, int numRows, const btConstraintArray& contacts, const btCholesky6& blockFactor);

#endif  // BT_SHOCK_PROPAGATION_LOAD_TRANSFER_H
