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
#include "BulletShockPropagation/btShockPropagationSettings.h"

/// "Fixate bottom-most objects of layer" (Erleben 2007) as an infinite-mass override of rows
/// Bullet has already set up for the whole step (D1). Private to the plugin (tests include it).
///
/// Why not zero btSolverBody's inverse mass alone: Bullet bakes each row's effective mass at
/// setup, m_jacDiagABInv = sor / (J_A W_A J_A^T + J_B W_B J_B^T + cfm), and stores W J^T of each
/// side in m_angularComponentA/B. So, for the layer's sweeps, with W_F = 0 on the fixated side F
/// and R the free side:
///   m_jacDiagABInv = sor / (J_R W_R J_R^T + cfm)          (effective mass of R alone)
///   m_angularComponentF = 0, and F's solver body gets zero inverse mass (impulses do not move F)
///   m_rhs = (error + J_F u_F^removed) * m_jacDiagABInv
/// where error is the row's velocity error as set up (rhs / old m_jacDiagABInv) and u^removed is
/// the part of F's motion the mode hides: nothing when the full motion is kept (F moves with the
/// velocity its own layer solved, which the sweeps read from F's solver body), F's tilt (its
/// rotation about axes across the contact normal) in the default mode, F's angular motion when
/// only the linear velocity is kept, all of it in zero-velocity mode. The row is
/// restored from a btFixationBackup after the layer; the btRigidBody is never modified.
enum btSolverRowKind
{
	BT_ROW_CONTACT,          ///< normal row (velocity error with external force and torque; cfm in the effective mass)
	BT_ROW_FRICTION,         ///< friction row (velocity error with external force only; relaxation sor)
	BT_ROW_ROLLING_FRICTION, ///< torsional or rolling friction row (relaxation 1)
	BT_ROW_JOINT             ///< btTypedConstraint row (velocity error weighted by damping; relaxation 1)
};

struct btLayerFixationParams
{
	btShockPropagationFixationMode m_mode = BT_FIXATION_KEEP_VELOCITY;
	btScalar m_sor = btScalar(1);           ///< btContactSolverInfo::m_sor of the step
	btScalar m_jointDamping = btScalar(1);  ///< btContactSolverInfo::m_damping of the step
	/// D14: a fixated end approaching the free end of a contact pushes it at most at the common
	/// velocity of an inelastic collision of the two (btShockPropagationSettings::m_inelasticFixation).
	bool m_inelasticFixation = true;
	/// D32 (m/s): a fixated end that nothing drives and whose shown motion along a contact,
	/// friction or rolling row is slower than this shows none (the convergence speed; 0: every
	/// motion is shown).
	btScalar m_restSpeed = btScalar(0);
};

/// What btFixateSolverRow changes, to undo it.
struct btFixationBackup
{
	btScalar m_jacDiagABInv;
	btScalar m_rhs;
	btScalar m_cfm;
	btVector3 m_angularComponentA;
	btVector3 m_angularComponentB;
};

inline btFixationBackup btBackupRow(const btSolverConstraint& row)
{
	return btFixationBackup{row.m_jacDiagABInv, row.m_rhs, row.m_cfm, row.m_angularComponentA, row.m_angularComponentB};
}

inline void btRestoreRow(btSolverConstraint& row, const btFixationBackup& backup)
{
	row.m_jacDiagABInv = backup.m_jacDiagABInv;
	row.m_rhs = backup.m_rhs;
	row.m_cfm = backup.m_cfm;
	row.m_angularComponentA = backup.m_angularComponentA;
	row.m_angularComponentB = backup.m_angularComponentB;
}

/// Re-derive one row with side A (fixA) or side B fixated. The bodies hold their current
/// velocities (call before the fixated body's inverse mass is zeroed). contactNormal: the normal
/// of the contact the row belongs to (contact, friction and rolling rows; zero for joints).
/// drivenA/B: a joint or a moving kinematic body drives the side, directly or through contacts
/// (btLayeredPasses::markDriven), so its slow motion is real and shown (D32 does not apply).
void btFixateSolverRow(btSolverConstraint& row, btSolverRowKind kind, const btSolverBody& bodyA, const btSolverBody& bodyB,
					   bool fixA, bool fixB, const btLayerFixationParams& params, const btVector3& contactNormal, bool drivenA = false,
					   bool drivenB = false);

#endif  // BT_SHOCK_PROPAGATION_LAYER_FIXATION_H
