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

#ifndef BT_SHOCK_PROPAGATION_WITHHELD_REACTIONS_H
#define BT_SHOCK_PROPAGATION_WITHHELD_REACTIONS_H

#include "BulletCollision/NarrowPhaseCollision/btManifoldPoint.h"
#include "BulletDynamics/ConstraintSolver/btSolverBody.h"
#include "LinearMath/btAlignedObjectArray.h"

/// The per-pass impulse bookkeeping of the layered step (private to the plugin).
///
/// Every row holds one impulse for the whole step (Bullet's m_appliedImpulse: warm start, global
/// pass, layer passes, weight pass, all accumulated; what apps read and what warm-starts the next
/// step). The global pass applies its share to both bodies of a row. A layer pass applies the
/// change it makes to a row only to the row's free end: the change is the reaction fixation
/// withholds from the fixated end, J_F^T (lambda_after - lambda_before), collected here per graph
/// node as a world-frame linear and angular impulse. Without weight feeling it is dropped (the
/// lower body does not feel the load, Erleben's method); with weight feeling (D13) the top-down
/// pass delivers it to the body before re-solving the body's layer.
class btWithheldReactions
{
public:
	void reset(int numNodes, int numContactRows);
	/// Withhold the impulse (linear, angular; world frame) from node.
	void add(int node, const btVector3& linear, const btVector3& angular)
	{
		m_linear[node] += linear;
		m_angular[node] += angular;
		m_has[node] = 1;
	}
	bool has(int node) const { return m_has[node] != 0; }
	/// Apply node's withheld impulse to its solver body (as a velocity change) and forget it.
	void deliver(int node, btSolverBody& body);
	/// Forget node's withheld impulse.
	void discard(int node);

	/// Per contact row: how much of its impulse its lower end did not feel this step.
	void holdBack(int contactRow, btScalar impulse) { m_heldBack[contactRow] += impulse; }
	btScalar heldBack(int contactRow) const { return m_heldBack[contactRow]; }

	/// The felt share F of a contact point's step impulse T: what both of its bodies received (the
	/// rest went to its upper body only). Kept between steps in btManifoldPoint::m_prevRHS, which
	/// Bullet's rigid-body solvers never read (its multibody solver does; that world is not
	/// supported). The warm start of the next step gives the lower body F, the upper body T.
	static btScalar feltShare(const btManifoldPoint& cp) { return cp.m_prevRHS; }
	static void setFeltShare(btManifoldPoint& cp, btScalar felt) { cp.m_prevRHS = felt; }

private:
	btAlignedObjectArray<btVector3> m_linear;
	btAlignedObjectArray<btVector3> m_angular;
	btAlignedObjectArray<char> m_has;
	btAlignedObjectArray<btScalar> m_heldBack;  // per contact row
};

#endif  // BT_SHOCK_PROPAGATION_WITHHELD_REACTIONS_H
