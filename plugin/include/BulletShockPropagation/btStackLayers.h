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

#ifndef BT_SHOCK_PROPAGATION_STACK_LAYERS_H
#define BT_SHOCK_PROPAGATION_STACK_LAYERS_H

#include "btContactGraph.h"
#include "btShockPropagationExport.h"

/// Stack layers of a contact graph (Erleben 2007, "Stack layers"; docs/design.md, section 3).
///
/// Definitions, for one connected component of the graph (components are found here, because
/// Bullet merges small islands into one solveGroup call):
///  - roots (static and kinematic bodies, BT_CONTACT_GRAPH_ROOT) have height 0;
///  - BFS height of a node = distance in edges from the nearest root (multi-source BFS), as in
///    Erleben 2007;
///  - support ordering (D12 in docs/design.md, in the spirit of Guendelman 2003): a body
///    that rests on another (btContactGraphEdge::m_support, from the contact normal against
///    gravity) must sit higher than it. Heights are raised along the support edges by a longest
///    path in topological order: h(u) = max(h_BFS(u), max over supports s of h(s) + 1). Without
///    support edges the heights are the BFS heights. A support cycle (possible only with tilted
///    contacts) keeps the heights its bodies had reached;
///  - layer of an edge (a, b) = max(h(a), h(b)) - 1, the layer in which its upper end is free
///    (equal heights: both free); with BFS heights this is min(h(a), h(b)) or h - 1; an edge to a
///    root is in layer h - 1;
///  - layer k solves its edges with the bodies of height k+1 free and the other ends (height
///    <= k) fixated (infinite mass); k = 0, 1, ..., K-1 bottom-up. A body of height h >= 1 is free
///    in exactly one layer (h-1), so gravity and the position update reach it once.
///    Example (the door of docs/design.md, D12): a lintel on a column of 2 boxes and one of 4 gets
///    height 5, above both column tops, so it is free only after both columns are solved, and
///    no body is clamped between two fixated ones.
///  - A component without a root (a falling cluster, decision D9) has no heights
///    (BT_STACK_HEIGHT_UNREACHED); all its bodies are free and all its edges are in layer 0,
///    where nothing of it is fixated: it is solved as one ordinary layer.
///
/// Cost O(nodes + edges). Bodies of equal height that touch (a ring of bricks) are free together
/// in one layer.
/// Internal part of btShockPropagationConstraintSolver; public so it can be tested and reused.
enum
{
	BT_STACK_HEIGHT_UNREACHED = -1
};

class BT_SHOCK_PROPAGATION_API btStackLayers
{
public:
	/// Analyse a graph whose adjacency has been built.
	void build(const btContactGraph& graph);

	int getNumComponents() const { return m_numComponents; }
	int getComponent(int body) const { return m_component[body]; }
	bool componentHasRoot(int component) const { return m_componentHasRoot[component] != 0; }

	/// 1 for a body touching a root, 2 above it, ...; BT_STACK_HEIGHT_UNREACHED without a root.
	int getHeight(int body) const { return m_height[body]; }
	int getEdgeLayer(int edge) const { return m_edgeLayer[edge]; }

	/// K: number of layers over all components (0 for a graph without nodes).
	int getNumLayers() const { return m_numLayers; }

	int getNumLayerEdges(int layer) const { return m_layerEdgeStart[layer + 1] - m_layerEdgeStart[layer]; }
	int getLayerEdge(int layer, int i) const { return m_layerEdges[m_layerEdgeStart[layer] + i]; }

	/// Bodies moved by the layer's solve (height layer+1, or unreached bodies in layer 0).
	int getNumFreeBodies(int layer) const { return m_layerFreeStart[layer + 1] - m_layerFreeStart[layer]; }
	int getFreeBody(int layer, int i) const { return m_layerFree[m_layerFreeStart[layer] + i]; }

	/// Bodies held at infinite mass in the layer's solve (height <= layer, with an edge in it).
	int getNumFixatedBodies(int layer) const { return m_layerFixedStart[layer + 1] - m_layerFixedStart[layer]; }
	int getFixatedBody(int layer, int i) const { return m_layerFixed[m_layerFixedStart[layer] + i]; }

	/// Largest number of free bodies in one layer.
	int getLargestLayer() const;
	/// Sum over layers of the fixated bodies.
	int getTotalFixated() const { return m_layerFixed.size(); }

private:
	void findComponents(const btContactGraph& graph);
	void computeHeights(const btContactGraph& graph);
	void raiseBySupport(const btContactGraph& graph);
	void assignLayers(const btContactGraph& graph);

	int m_numComponents = 0;
	int m_numLayers = 0;
	btAlignedObjectArray<int> m_component;
	btAlignedObjectArray<char> m_componentHasRoot;
	btAlignedObjectArray<int> m_height;
	btAlignedObjectArray<int> m_edgeLayer;
	btAlignedObjectArray<int> m_queue;
	btAlignedObjectArray<int> m_numSupports;  // per body: support edges below it not yet processed

	btAlignedObjectArray<int> m_layerEdgeStart, m_layerEdges;
	btAlignedObjectArray<int> m_layerFreeStart, m_layerFree;
	btAlignedObjectArray<int> m_layerFixedStart, m_layerFixed;
	btAlignedObjectArray<int> m_lastFixedLayer;  // per body: last layer it was listed fixated in
	btAlignedObjectArray<int> m_keys, m_values, m_cursor;  // scratch of assignLayers, kept so steps do not allocate
};

#endif  // BT_SHOCK_PROPAGATION_STACK_LAYERS_H
