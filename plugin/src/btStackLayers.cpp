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

// Stack analysis after K. Erleben, "Velocity-Based Shock Propagation for Multibody Dynamics
// Animation", ACM TOG 26(2), 2007, with per-component analysis (docs/design.md, section 3).

#include "BulletShockPropagation/btStackLayers.h"

#include "LinearMath/btMinMax.h"

namespace
{
// Counting sort of (key, value) pairs into CSR arrays: start[k]..start[k+1] holds the values
// with key k, in input order. cursor is scratch (kept by the caller so steps do not allocate).
void bucketByKey(const btAlignedObjectArray<int>& keys, const btAlignedObjectArray<int>& values, int numKeys,
				 btAlignedObjectArray<int>& start, btAlignedObjectArray<int>& out, btAlignedObjectArray<int>& cursor)
{
	start.resize(numKeys + 1);
	for (int k = 0; k <= numKeys; ++k) start[k] = 0;
	for (int i = 0; i < keys.size(); ++i) ++start[keys[i] + 1];
	for (int k = 0; k < numKeys; ++k) start[k + 1] += start[k];
	out.resize(keys.size());
	cursor.resize(numKeys);
	for (int k = 0; k < numKeys; ++k) cursor[k] = start[k];
	for (int i = 0; i < keys.size(); ++i) out[cursor[keys[i]]++] = values[i];
}
}  // namespace

void btStackLayers::build(const btContactGraph& graph)
{
	findComponents(graph);
	computeHeights(graph);
	raiseBySupport(graph);
	assignLayers(graph);
}

void btStackLayers::findComponents(const btContactGraph& graph)
{
	const int n = graph.getNumBodies();
	m_component.resize(n);
	for (int b = 0; b < n; ++b) m_component[b] = -1;
	m_componentHasRoot.resize(0);
	m_numComponents = 0;
	m_queue.resize(n);

	// Flood fill over node-node edges; a component touches a root if any of its edges does.
	for (int seed = 0; seed < n; ++seed)
	{
		if (m_component[seed] >= 0) continue;
		const int c = m_numComponents++;
		m_componentHasRoot.push_back(0);
		int head = 0, tail = 0;
		m_queue[tail++] = seed;
		m_component[seed] = c;
		while (head < tail)
		{
			const int a = m_queue[head++];
			for (int i = 0; i < graph.getNumIncidentEdges(a); ++i)
			{
				const int b = graph.getOtherBody(graph.getIncidentEdge(a, i), a);
				if (b == BT_CONTACT_GRAPH_ROOT)
				{
					m_componentHasRoot[c] = 1;
				}
				else if (m_component[b] < 0)
				{
					m_component[b] = c;
					m_queue[tail++] = b;
				}
			}
		}
	}
}

void btStackLayers::computeHeights(const btContactGraph& graph)
{
	const int n = graph.getNumBodies();
	m_height.resize(n);
	int head = 0, tail = 0;
	// All roots at once: every node with an edge to a root starts the BFS at height 1.
	for (int b = 0; b < n; ++b)
	{
		m_height[b] = BT_STACK_HEIGHT_UNREACHED;
		for (int i = 0; i < graph.getNumIncidentEdges(b); ++i)
		{
			if (graph.getOtherBody(graph.getIncidentEdge(b, i), b) == BT_CONTACT_GRAPH_ROOT)
			{
				m_height[b] = 1;
				m_queue[tail++] = b;
				break;
			}
		}
	}
	// h(b) = min over neighbours a of h(a) + 1
	while (head < tail)
	{
		const int a = m_queue[head++];
		for (int i = 0; i < graph.getNumIncidentEdges(a); ++i)
		{
			const int b = graph.getOtherBody(graph.getIncidentEdge(a, i), a);
			if (b >= 0 && m_height[b] == BT_STACK_HEIGHT_UNREACHED)
			{
				m_height[b] = m_height[a] + 1;
				m_queue[tail++] = b;
			}
		}
	}
}

namespace
{
/// The body of `edge` that rests on the other one, or -1 (side contact, joint, root end).
int upperEnd(const btContactGraphEdge& edge)
{
	if (edge.m_bodyA < 0 || edge.m_bodyB < 0) return -1;
	if (edge.m_support == BT_SUPPORT_A_ON_B) return edge.m_bodyA;
	if (edge.m_support == BT_SUPPORT_B_ON_A) return edge.m_bodyB;
	return -1;
}
}  // namespace

void btStackLayers::raiseBySupport(const btContactGraph& graph)
{
	// Longest path over the support edges (lower -> upper), Kahn's topological order, starting
	// from the BFS heights. Bodies without a root keep BT_STACK_HEIGHT_UNREACHED.
	const int n = graph.getNumBodies();
	m_numSupports.resize(n);
	for (int b = 0; b < n; ++b) m_numSupports[b] = 0;
	bool any = false;
	for (int e = 0; e < graph.getNumEdges(); ++e)
	{
		const int upper = upperEnd(graph.getEdge(e));
		if (upper >= 0 && m_height[upper] != BT_STACK_HEIGHT_UNREACHED)
		{
			++m_numSupports[upper];
			any = true;
		}
	}
	if (!any) return;
	int head = 0, tail = 0;
	for (int b = 0; b < n; ++b)
	{
		if (m_numSupports[b] == 0 && m_height[b] != BT_STACK_HEIGHT_UNREACHED) m_queue[tail++] = b;
	}
	while (head < tail)
	{
		const int lower = m_queue[head++];
		for (int i = 0; i < graph.getNumIncidentEdges(lower); ++i)
		{
			const int e = graph.getIncidentEdge(lower, i);
			const int upper = upperEnd(graph.getEdge(e));
			if (upper < 0 || upper == lower || m_height[upper] == BT_STACK_HEIGHT_UNREACHED) continue;
			m_height[upper] = btMax(m_height[upper], m_height[lower] + 1);
			if (--m_numSupports[upper] == 0) m_queue[tail++] = upper;
		}
	}
}

void btStackLayers::assignLayers(const btContactGraph& graph)
{
	const int n = graph.getNumBodies();
	const int numEdges = graph.getNumEdges();

	// K = max height (a body of height h is free in layer h-1); unreached bodies use layer 0.
	m_numLayers = 0;
	for (int b = 0; b < n; ++b)
	{
		const int layer = m_height[b] == BT_STACK_HEIGHT_UNREACHED ? 0 : m_height[b] - 1;
		m_numLayers = btMax(m_numLayers, layer + 1);
	}

	btAlignedObjectArray<int>& keys = m_keys;
	btAlignedObjectArray<int>& values = m_values;

	// Edge layers.
	m_edgeLayer.resize(numEdges);
	keys.resize(numEdges);
	values.resize(numEdges);
	for (int e = 0; e < numEdges; ++e)
	{
		const btContactGraphEdge& edge = graph.getEdge(e);
		const int ha = edge.m_bodyA == BT_CONTACT_GRAPH_ROOT ? 0 : m_height[edge.m_bodyA];
		const int hb = edge.m_bodyB == BT_CONTACT_GRAPH_ROOT ? 0 : m_height[edge.m_bodyB];
		int layer;
		if (ha == BT_STACK_HEIGHT_UNREACHED || hb == BT_STACK_HEIGHT_UNREACHED)
			layer = 0;  // root-less component: one un-fixated layer
		else
			layer = btMax(ha, hb) - 1;  // the layer in which the upper end is free
		m_edgeLayer[e] = layer;
		keys[e] = layer;
		values[e] = e;
	}
	bucketByKey(keys, values, m_numLayers, m_layerEdgeStart, m_layerEdges, m_cursor);

	// Free bodies.
	keys.resize(n);
	values.resize(n);
	for (int b = 0; b < n; ++b)
	{
		keys[b] = m_height[b] == BT_STACK_HEIGHT_UNREACHED ? 0 : m_height[b] - 1;
		values[b] = b;
	}
	bucketByKey(keys, values, m_numLayers, m_layerFreeStart, m_layerFree, m_cursor);

	// Fixated bodies: the lower ends (height <= layer) of the layer's edges, each listed once.
	keys.resize(0);
	values.resize(0);
	m_lastFixedLayer.resize(n);
	for (int b = 0; b < n; ++b) m_lastFixedLayer[b] = -1;
	for (int k = 1; k < m_numLayers; ++k)
	{
		for (int i = 0; i < getNumLayerEdges(k); ++i)
		{
			const btContactGraphEdge& edge = graph.getEdge(getLayerEdge(k, i));
			const int ends[2] = {edge.m_bodyA, edge.m_bodyB};
			for (int j = 0; j < 2; ++j)
			{
				const int b = ends[j];
				if (b >= 0 && m_height[b] <= k && m_height[b] != BT_STACK_HEIGHT_UNREACHED && m_lastFixedLayer[b] != k)
				{
					m_lastFixedLayer[b] = k;
					keys.push_back(k);
					values.push_back(b);
				}
			}
		}
	}
	bucketByKey(keys, values, m_numLayers, m_layerFixedStart, m_layerFixed, m_cursor);
}

int btStackLayers::getLargestLayer() const
{
	int largest = 0;
	for (int k = 0; k < m_numLayers; ++k) largest = btMax(largest, getNumFreeBodies(k));
	return largest;
}
