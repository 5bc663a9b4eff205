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

// The solver's input: bodies, manifolds and joints checked (bad input, D9), the contact graph
// and its stack layers (D8, D12).

#include "BulletShockPropagation/btShockPropagationConstraintSolver.h"

#include "btBodyChecks.h"

#include <cstdio>

using namespace btShockPropagationChecks;

void btShockPropagationConstraintSolver::filterInput(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds,
													 int numManifolds, btTypedConstraint** constraints, int numConstraints, bool countInStatistics)
{
	m_bodies.resize(0);
	m_manifolds.resize(0);
	m_constraints.resize(0);
	int skippedBodies = 0;
	for (int i = 0; i < numBodies; ++i)
	{
		if (!isHealthy(bodies[i])) ++skippedBodies;
		else if (isNode(bodies[i])) m_bodies.push_back(bodies[i]);
	}
	int skippedManifolds = 0;
	for (int i = 0; i < numManifolds; ++i)
	{
		const btPersistentManifold* m = manifolds[i];
		if (isHealthy(m->getBody0()) && isHealthy(m->getBody1()) && hasFinitePoints(m)) m_manifolds.push_back(manifolds[i]);
		else ++skippedManifolds;
	}
	for (int i = 0; i < numConstraints; ++i)
	{
		if (isHealthy(&constraints[i]->getRigidBodyA()) && isHealthy(&constraints[i]->getRigidBodyB())) m_constraints.push_back(constraints[i]);
	}
	if (!countInStatistics) return;
	if ((skippedBodies || skippedManifolds) && !m_warnedNonFinite)
	{
		m_warnedNonFinite = true;
		std::fprintf(stderr,
					 "BulletShockPropagation: %d body(ies) with a NaN/Inf transform or velocity and %d manifold(s) touching them "
					 "are left out of the solve (warned once; see getStatistics().m_numSkippedBodies)\n",
					 skippedBodies, skippedManifolds);
	}
	m_stats.m_numSkippedBodies += skippedBodies;
	m_stats.m_numSkippedManifolds += skippedManifolds;
}

int btShockPropagationConstraintSolver::nodeOf(const btCollisionObject* object) const
{
	const int id = object->getCompanionId();
	return (id >= 0 && id < m_bodies.size() && m_bodies[id] == object) ? id : int(BT_CONTACT_GRAPH_ROOT);
}

void btShockPropagationConstraintSolver::buildGraph()
{
	const int n = m_bodies.size();
	m_graph.reset(n);
	// Bullet keeps companion ids at -1 between solves; borrow them as node indices meanwhile.
	for (int i = 0; i < n; ++i) m_bodies[i]->setCompanionId(i);
	m_edgeOfManifold.resize(m_manifolds.size());
	for (int i = 0; i < m_manifolds.size(); ++i)
	{
		const btPersistentManifold* m = m_manifolds[i];
		const btVector3 up = m_settings.m_diagnostics.m_supportOrdering ? upOf(m) : btVector3(0, 0, 0);
		m_edgeOfManifold[i] = m_graph.addManifold(m, nodeOf(m->getBody0()), nodeOf(m->getBody1()), i, up, m_settings.m_diagnostics.m_supportAngle);
	}
	// D8: joints are no edges. Fixating one end of a joint against the other clamps every body of
	// a closed chain (a bridge anchored at both ends) between two fixated neighbours, which fight
	// (measured: the hinge bridge never settles, 1.2 m/s after 10 s). Joint rows are swept by the
	// corrector, every body free; mechanisms without stacks are Bullet's.
	for (int i = 0; i < n; ++i) m_bodies[i]->setCompanionId(-1);
	m_graph.buildAdjacency();
	m_layers.build(m_graph);
}
