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

#include "BulletShockPropagation/btContactGraph.h"

#include "BulletCollision/NarrowPhaseCollision/btPersistentManifold.h"

void btContactGraph::reset(int numBodies)
{
	btAssert(numBodies >= 0);
	m_numBodies = numBodies;
	m_edges.resize(0);
	m_adjacencyStart.resize(0);
	m_adjacency.resize(0);
}

int btContactGraph::addEdge(int bodyA, int bodyB, int source, int support)
{
	btAssert(bodyA >= BT_CONTACT_GRAPH_ROOT && bodyA < m_numBodies);
	btAssert(bodyB >= BT_CONTACT_GRAPH_ROOT && bodyB < m_numBodies);
	if (bodyA == BT_CONTACT_GRAPH_ROOT && bodyB == BT_CONTACT_GRAPH_ROOT)
	{
		return -1;
	}
	btContactGraphEdge& e = m_edges.expandNonInitializing();
	e.m_bodyA = bodyA;
	e.m_bodyB = bodyB;
	e.m_source = source;
	e.m_support = support;
	return m_edges.size() - 1;
}

void btContactGraph::buildAdjacency()
{
	// Counting sort of edge ends by node: O(nodes + edges), insertion order kept per node.
	m_adjacencyStart.resize(m_numBodies + 1);
	for (int i = 0; i <= m_numBodies; ++i)
	{
		m_adjacencyStart[i] = 0;
	}
	for (int e = 0; e < m_edges.size(); ++e)
	{
		const btContactGraphEdge& edge = m_edges[e];
		if (edge.m_bodyA >= 0) ++m_adjacencyStart[edge.m_bodyA + 1];
		if (edge.m_bodyB >= 0 && edge.m_bodyB != edge.m_bodyA) ++m_adjacencyStart[edge.m_bodyB + 1];
	}
	for (int i = 0; i < m_numBodies; ++i)
	{
		m_adjacencyStart[i + 1] += m_adjacencyStart[i];
	}
	m_adjacency.resize(m_adjacencyStart[m_numBodies]);

	btAlignedObjectArray<int>& cursor = m_cursor;
	cursor.resize(m_numBodies);
	for (int i = 0; i < m_numBodies; ++i)
	{
		cursor[i] = m_adjacencyStart[i];
	}
	for (int e = 0; e < m_edges.size(); ++e)
	{
		const btContactGraphEdge& edge = m_edges[e];
		if (edge.m_bodyA >= 0) m_adjacency[cursor[edge.m_bodyA]++] = e;
		if (edge.m_bodyB >= 0 && edge.m_bodyB != edge.m_bodyA) m_adjacency[cursor[edge.m_bodyB]++] = e;
	}
}

bool btContactGraph::isContactEdge(const btPersistentManifold* manifold)
{
	const btScalar threshold = manifold->getContactProcessingThreshold();
	for (int j = 0; j < manifold->getNumContacts(); ++j)
	{
		if (manifold->getContactPoint(j).getDistance() <= threshold) return true;
	}
	return false;
}

int btContactGraph::supportOf(const btPersistentManifold* manifold, const btVector3& up, btScalar supportAngle)
{
	// m_normalWorldOnB points from body 1 to body 0: up means body 0 (A) rests on body 1 (B).
	if (manifold->getNumContacts() == 0 || up.isZero()) return BT_SUPPORT_NONE;
	btVector3 normal(0, 0, 0);
	for (int j = 0; j < manifold->getNumContacts(); ++j) normal += manifold->getContactPoint(j).m_normalWorldOnB;
	const btScalar length = normal.length();
	if (!(length > SIMD_EPSILON)) return BT_SUPPORT_NONE;
	const btScalar cosine = normal.dot(up) / length;
	const btScalar threshold = btCos(supportAngle);
	if (cosine > threshold) return BT_SUPPORT_A_ON_B;
	if (cosine < -threshold) return BT_SUPPORT_B_ON_A;
	return BT_SUPPORT_NONE;
}

int btContactGraph::addManifold(const btPersistentManifold* manifold, int nodeA, int nodeB, int source, const btVector3& up, btScalar supportAngle)
{
	if (!isContactEdge(manifold)) return -1;
	return addEdge(nodeA, nodeB, source, supportOf(manifold, up, supportAngle));
}
