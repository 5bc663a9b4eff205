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

#ifndef BT_SHOCK_PROPAGATION_LAYER_FIXATION_H
#define BT_SHOCK_PROPAGATION_LAYER_FIXATION_H

#include "BulletDynamics/ConstraintSolver/btSolverBody.h"
#include "BulletDynamics/ConstraintSolver/btSolverConstraint.h"
#include "btShockPropagationSettings.h"

/// "Fixate bottom-most objects of layer" (Erleben 2007) as an infinite-mass override of the
/// solver rows Bullet has already built for one layer.
///
/// Why not zero btSolverBody::m_invMass alone: Bullet bakes the effective mass of every row at
/// setup from the btRigidBody, m_jacDiagABInv = sor / (J_A W_A J_A^T + J_B W_B J_B^T + cfm), and
/// stores W J^T of each side in m_angularComponentA/B. Zeroing the solver body's inverse mass
/// would leave the fixated body's inverse inertia in both, so impulses would be sized for a
/// body that can still give way. Why not change the btRigidBody's mass (setMassProps) for the
/// layer: its inverse mass, inverse inertia and gravity are private and are recomputed as 1/m,
/// which does not round-trip exactly in floating point.
///
/// So, with W_F = 0 for a fixated side F and the free side R:
///   m_jacDiagABInv = sor / (J_R W_R J_R^T + cfm)                 (effective mass of R alone)
///   m_angularComponentF = 0,  solver body F: m_invMass = 0      (impulses do not move F)
///   m_rhs = (b + J_F u_F^ext) * m_jacDiagABInv                  (F gets no gravity impulse this
///                                                               layer; in zero-velocity mode
///                                                               also + J_F u_F: F is at rest)
/// and the fixated solver body is detached from its btRigidBody (m_originalBody = 0), so the
/// write-back leaves the fixated body exactly as it was. The btRigidBody is never modified.
/// Internal part of btShockPropagationConstraintSolver; public so it can be tested and reused.
enum btSolverRowKind
{
	BT_ROW_CONTACT,          ///< normal row (rhs uses external force and torque; cfm scales with the effective mass)
	BT_ROW_FRICTION,         ///< friction row (rhs uses external force only; relaxation sor)
	BT_ROW_ROLLING_FRICTION, ///< torsional or rolling friction row (relaxation 1)
	BT_ROW_JOINT             ///< btTypedConstraint row (rhs damping-weighted; relaxation 1)
};

struct btLayerFixationParams
{
	btShockPropagationFixationMode m_mode = BT_FIXATION_KEEP_VELOCITY;
	btScalar m_sor = btScalar(1);           ///< btContactSolverInfo::m_sor of the solve
	btScalar m_jointDamping = btScalar(1);  ///< btContactSolverInfo::m_damping of the solve
	/// D14: at a contact whose fixated end F approaches the free end R, F pushes R at most at the
	/// common normal velocity of an inelastic collision of the two, (m_F a_F + m_R a_R) / (m_F + m_R)
	/// with the row's effective masses, instead of at F's own speed (btShockPropagationSettings).
	bool m_inelasticFixation = false;
};

/// J u of a fixated end along a row, as the layer passes let it move (D1): its linear velocity,
/// plus its angular velocity when the full velocity is kept; 0 in zero-velocity mode.
btScalar btFixatedEndVelocity(const btSolverBody& body, const btVector3& linearAxis, const btVector3& angularAxis,
							  btShockPropagationFixationMode mode);

/// D14: the speed (>= 0) at which a fixated end F that approaches a free end R at `approach`
/// (m/s along the row, > 0 towards R) may push R, which moves away from F at `away`: the common
/// velocity of an inelastic collision of the two, (approach w_R + away w_F) / (w_F + w_R), where
/// w = J W J^T of each end, and never below zero (F is then held still along the row, a support).
/// Returns `approach` unchanged when F does not catch up with R.
btScalar btInelasticApproach(btScalar approach, btScalar away, btScalar wFixated, btScalar wFree);

/// Re-derive one row for fixated sides. fixA / fixB say which ends are fixated. The bodies must
/// still hold the data Bullet set them up with (call before btFixateSolverBody).
void btFixateSolverRow(btSolverConstraint& row, btSolverRowKind kind, const btSolverBody& bodyA, const btSolverBody& bodyB,
					   bool fixA, bool fixB, const btLayerFixationParams& params);

/// Take the external impulse (gravity, gyroscopic torque) of side A and/or B out of a row's
/// right-hand side, for a re-solve within a step whose external impulses the bodies already
/// received (the weight-feeling pass). Call before btFixateSolverRow, then zero the bodies'
/// m_externalForceImpulse and m_externalTorqueImpulse.
void btRemoveExternalImpulse(btSolverConstraint& row, btSolverRowKind kind, const btSolverBody& bodyA, const btSolverBody& bodyB,
							 bool sideA, bool sideB, btScalar jointDamping);

/// Turn a solver body into an infinite-mass obstacle for the rest of this solve (after its rows
/// were re-derived): zero inverse mass, no external impulse, no accumulated delta velocity, and
/// detached from its btRigidBody so the write-back skips it. Returns the detached btRigidBody.
btRigidBody* btFixateSolverBody(btSolverBody& body, btShockPropagationFixationMode mode);

#endif  // BT_SHOCK_PROPAGATION_LAYER_FIXATION_H
