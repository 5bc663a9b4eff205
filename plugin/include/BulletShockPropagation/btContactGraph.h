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

#ifndef BT_SHOCK_PROPAGATION_CONTACT_GRAPH_H
#define BT_SHOCK_PROPAGATION_CONTACT_GRAPH_H

#include "LinearMath/btAlignedObjectArray.h"
#include "LinearMath/btScalar.h"
#include "LinearMath/btVector3.h"
#include "btShockPropagationExport.h"

class btPersistentManifold;

/// The contact graph of one solveGroup call (Erleben 2007, "Contact graph"; the idea of
/// shock propagation over a contact graph is Guendelman, Bridson and Fedkiw 2003).
///
/// Nodes are the dynamic bodies of the group, numbered 0..n-1 by the caller. An edge is a
/// body pair that touches (a persistent manifold with at least one point within the graph
/// threshold, decision D8) or is joined (a btTypedConstraint). Static and kinematic bodies are
/// not nodes: they are the roots of the BFS and are all written as body index -1
/// (BT_CONTACT_GRAPH_ROOT). Several manifolds or joints between the same pair are several edges;
/// the layering treats them alike.
///
/// The graph itself is pure data (edges between node indices), so graph code is tested on
/// hand-built inputs (tests/unit); addManifold is the one place where a Bullet manifold becomes
/// an edge (the edge rule, D8, and the support direction, D12), used by the solver and timed by
/// demos/bench.
/// Internal part of btShockPropagationConstraintSolver; public so it can be tested and reused.
enum
{
	BT_CONTACT_GRAPH_ROOT = -1
};

struct btContactGraphEdge
{
	int m_bodyA;   ///< node index, or BT_CONTACT_GRAPH_ROOT
	int m_bodyB;   ///< node index, or BT_CONTACT_GRAPH_ROOT
	int m_source;  ///< caller's handle: index of the manifold or constraint this edge stands for
	/// Which end rests on the other, from the contact normals and gravity:
	/// BT_SUPPORT_A_ON_B (A rests on B), BT_SUPPORT_B_ON_A, or BT_SUPPORT_NONE (side contact, joint).
	int m_support;
};

enum btContactSupport
{
	BT_SUPPORT_NONE = 0,
	BT_SUPPORT_A_ON_B = 1,
	BT_SUPPORT_B_ON_A = -1
};

class BT_SHOCK_PROPAGATION_API btContactGraph
{
public:
	/// Forget all edges; the graph gets numBodies nodes.
	void reset(int numBodies);

	/// Add an edge; at least one end must be a node. An edge between two roots is ignored.
	/// `support` says which end rests on the other (btContactSupport). Returns the edge index,
	/// or -1 if ignored.
	int addEdge(int bodyA, int bodyB, int source, int support = BT_SUPPORT_NONE);

	/// The edge rule (D8): a manifold is an edge if it holds a point Bullet makes a solver row of
	/// (distance within the manifold's contact processing threshold), so every contact row of a
	/// step lies in exactly one layer. Bullet keeps points up to its contact breaking threshold,
	/// which scales with the shapes (relative breaking threshold), and speculative (CCD) points.
	static bool isContactEdge(const btPersistentManifold* manifold);

	/// Which body of the manifold rests on the other (btContactSupport): the mean contact normal
	/// against `up` (unit vector, -gravity / |g|), within supportAngle (radians) of vertical.
	static int supportOf(const btPersistentManifold* manifold, const btVector3& up, btScalar supportAngle);

	/// addEdge for a manifold that passes isContactEdge (nodeA / nodeB: its bodies' node indices
	/// or BT_CONTACT_GRAPH_ROOT). up: unit up vector, or zero for no support ordering. Returns the
	/// edge index, or -1 if the manifold is no edge.
	int addManifold(const btPersistentManifold* manifold, int nodeA, int nodeB, int source, const btVector3& up, btScalar supportAngle);

	/// Build the adjacency lists (call after the last addEdge, before queries below).
	void buildAdjacency();

	int getNumBodies() const { return m_numBodies; }
	int getNumEdges() const { return m_edges.size(); }
	const btContactGraphEdge& getEdge(int edge) const { return m_edges[edge]; }

	/// Edges incident to a node, in insertion order: indices into getEdge().
	int getNumIncidentEdges(int body) const { return m_adjacencyStart[body + 1] - m_adjacencyStart[body]; }
	int getIncidentEdge(int body, int i) const { return m_adjacency[m_adjacencyStart[body] + i]; }

	/// The other end of an edge seen from body (may be BT_CONTACT_GRAPH_ROOT).
	int getOtherBody(int edge, int body) const
	{
		const btContactGraphEdge& e = m_edges[edge];
		return e.m_bodyA == body ? e.m_bodyB : e.m_bodyA;
	}

private:
	int m_numBodies = 0;
	btAlignedObjectArray<btContactGraphEdge> m_edges;
	btAlignedObjectArray<int> m_adjacencyStart;  // CSR offsets, size n+1
	btAlignedObjectArray<int> m_adjacency;       // edge indices, two entries per dynamic-dynamic edge
	btAlignedObjectArray<int> m_cursor;          // scratch for buildAdjacency, kept to reuse its memory
};

#endif  // BT_SHOCK_PROPAGATION_CONTACT_GRAPH_H
