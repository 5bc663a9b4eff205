// Graph and layer specs on hand-built inputs, with no Bullet world (docs/design.md, section 3).
#include <BulletShockPropagation/btStackLayers.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <random>
#include <set>
#include <vector>

namespace
{
const int R = BT_CONTACT_GRAPH_ROOT;

struct Graph
{
	btContactGraph graph;
	btStackLayers layers;
	/// `supports[i]` is the btContactSupport of edge i (none if the list is shorter).
	Graph(int n, const std::vector<std::pair<int, int>>& edges, const std::vector<int>& supports = {})
	{
		graph.reset(n);
		for (size_t i = 0; i < edges.size(); ++i)
			graph.addEdge(edges[i].first, edges[i].second, int(i), i < supports.size() ? supports[i] : int(BT_SUPPORT_NONE));
		graph.buildAdjacency();
		layers.build(graph);
	}
	std::set<int> freeBodies(int k) const
	{
		std::set<int> s;
		for (int i = 0; i < layers.getNumFreeBodies(k); ++i) s.insert(layers.getFreeBody(k, i));
		return s;
	}
	std::set<int> fixatedBodies(int k) const
	{
		std::set<int> s;
		for (int i = 0; i < layers.getNumFixatedBodies(k); ++i) s.insert(layers.getFixatedBody(k, i));
		return s;
	}
};

// A vertical chain: ground - 0 - 1 - ... - (n-1).
std::vector<std::pair<int, int>> chain(int n)
{
	std::vector<std::pair<int, int>> e{{R, 0}};
	for (int i = 1; i < n; ++i) e.push_back({i - 1, i});
	return e;
}
}  // namespace

TEST(StackLayers, BoxOnGroundIsLayerZero)
{
	Graph g(1, {{0, R}});
	EXPECT_EQ(g.layers.getHeight(0), 1);
	EXPECT_EQ(g.layers.getNumLayers(), 1);
	EXPECT_EQ(g.layers.getEdgeLayer(0), 0);
	EXPECT_EQ(g.freeBodies(0), std::set<int>({0}));
	EXPECT_TRUE(g.fixatedBodies(0).empty());
}

TEST(StackLayers, ChainHeightEqualsDistanceFromGround)
{
	const int n = 6;
	Graph g(n, chain(n));
	ASSERT_EQ(g.layers.getNumLayers(), n);
	for (int i = 0; i < n; ++i)
	{
		EXPECT_EQ(g.layers.getHeight(i), i + 1);
		EXPECT_EQ(g.layers.getEdgeLayer(i), i) << "edge below body " << i;
		EXPECT_EQ(g.freeBodies(i), std::set<int>({i}));
		if (i > 0) { EXPECT_EQ(g.fixatedBodies(i), std::set<int>({i - 1})); }
	}
	EXPECT_EQ(g.layers.getTotalFixated(), n - 1);  // the top body supports nothing
}

TEST(StackLayers, PyramidLayerEqualsRowIndex)
{
	// Rows of 4, 3, 2, 1 boxes; each box rests on the two below it, neighbours in a row touch.
	std::vector<int> rowStart{0, 4, 7, 9, 10};
	std::vector<std::pair<int, int>> e;
	for (int row = 0; row < 4; ++row)
	{
		const int count = 4 - row;
		for (int i = 0; i < count; ++i)
		{
			const int b = rowStart[row] + i;
			if (row == 0) e.push_back({R, b});
			else
			{
				e.push_back({rowStart[row - 1] + i, b});
				e.push_back({rowStart[row - 1] + i + 1, b});
			}
			if (i > 0) e.push_back({b - 1, b});
		}
	}
	Graph g(10, e);
	EXPECT_EQ(g.layers.getNumLayers(), 4);
	for (int row = 0; row < 4; ++row)
	{
		for (int b = rowStart[row]; b < rowStart[row + 1]; ++b) EXPECT_EQ(g.layers.getHeight(b), row + 1);
		std::set<int> rowBodies;
		for (int b = rowStart[row]; b < rowStart[row + 1]; ++b) rowBodies.insert(b);
		EXPECT_EQ(g.freeBodies(row), rowBodies);
	}
	// Side contacts within a row go to the layer where both are free: row r -> layer r.
	for (int i = 0; i < g.graph.getNumEdges(); ++i)
	{
		const btContactGraphEdge& edge = g.graph.getEdge(i);
		if (edge.m_bodyA != R && g.layers.getHeight(edge.m_bodyA) == g.layers.getHeight(edge.m_bodyB))
		{
			EXPECT_EQ(g.layers.getEdgeLayer(i), g.layers.getHeight(edge.m_bodyA) - 1);
		}
	}
}

TEST(StackLayers, RunningBondWallRowsAreLayers)
{
	// 3 rows of 3 bricks offset by half a brick: each brick rests on two below (ends on one).
	std::vector<std::pair<int, int>> e{{R, 0}, {R, 1}, {R, 2}, {0, 1}, {1, 2}};
	e.insert(e.end(), {{0, 3}, {1, 3}, {1, 4}, {2, 4}, {2, 5}, {3, 4}, {4, 5}});
	e.insert(e.end(), {{3, 6}, {3, 7}, {4, 7}, {4, 8}, {5, 8}, {6, 7}, {7, 8}});
	Graph g(9, e);
	EXPECT_EQ(g.layers.getNumLayers(), 3);
	EXPECT_EQ(g.freeBodies(2), std::set<int>({6, 7, 8}));
	EXPECT_EQ(g.fixatedBodies(2), std::set<int>({3, 4, 5}));
	EXPECT_EQ(g.fixatedBodies(1), std::set<int>({0, 1, 2}));
}

TEST(StackLayers, RingOfBricksIsOneLayerWithItsCycle)
{
	// A ring of 8 bricks on the ground, each touching its two neighbours: a contact cycle.
	std::vector<std::pair<int, int>> e;
	for (int i = 0; i < 8; ++i)
	{
		e.push_back({R, i});
		e.push_back({i, (i + 1) % 8});
	}
	Graph g(8, e);
	EXPECT_EQ(g.layers.getNumLayers(), 1);
	EXPECT_EQ(g.layers.getNumLayerEdges(0), 16);
	EXPECT_EQ(g.freeBodies(0).size(), 8u);
	EXPECT_EQ(g.layers.getTotalFixated(), 0);
}

TEST(StackLayers, ContactCycleAboveGroundTerminatesWithBfsHeights)
{
	// 0 on ground; 1 and 2 on 0; 3 on 1 and 2; 1-2 touch; 3 also touches 0 (a cycle 0-1-3-0).
	Graph g(4, {{R, 0}, {0, 1}, {0, 2}, {1, 2}, {1, 3}, {2, 3}, {0, 3}});
	EXPECT_EQ(g.layers.getHeight(0), 1);
	EXPECT_EQ(g.layers.getHeight(1), 2);
	EXPECT_EQ(g.layers.getHeight(3), 2);  // shortest path, not physical order
	EXPECT_EQ(g.layers.getNumLayers(), 2);
}

TEST(StackLayers, TwoSeparateGroundsAreTwoComponents)
{
	Graph g(4, {{R, 0}, {0, 1}, {R, 2}, {2, 3}});
	EXPECT_EQ(g.layers.getNumComponents(), 2);
	EXPECT_TRUE(g.layers.componentHasRoot(g.layers.getComponent(0)));
	EXPECT_TRUE(g.layers.componentHasRoot(g.layers.getComponent(2)));
	EXPECT_NE(g.layers.getComponent(0), g.layers.getComponent(2));
	EXPECT_EQ(g.freeBodies(1), std::set<int>({1, 3}));  // same layer across components
}

TEST(StackLayers, FloatingClusterWithoutRootIsOneUnfixatedLayer)
{
	// 0-1-2 touch each other but nothing static; 3 stands on the ground.
	Graph g(4, {{0, 1}, {1, 2}, {R, 3}});
	EXPECT_FALSE(g.layers.componentHasRoot(g.layers.getComponent(0)));
	for (int b = 0; b < 3; ++b) EXPECT_EQ(g.layers.getHeight(b), BT_STACK_HEIGHT_UNREACHED);
	EXPECT_EQ(g.freeBodies(0), std::set<int>({0, 1, 2, 3}));
	EXPECT_EQ(g.layers.getEdgeLayer(0), 0);
	EXPECT_EQ(g.layers.getEdgeLayer(1), 0);
	EXPECT_EQ(g.layers.getTotalFixated(), 0);
}

TEST(StackLayers, IsolatedBodyIsFreeInLayerZero)
{
	Graph g(2, {{R, 1}});
	EXPECT_EQ(g.layers.getHeight(0), BT_STACK_HEIGHT_UNREACHED);
	EXPECT_EQ(g.freeBodies(0), std::set<int>({0, 1}));
}

TEST(StackLayers, KinematicRootStartsTheBfsLikeStatic)
{
	// A kinematic platform is a root too (written as R): the box on it is height 1.
	Graph g(2, {{0, R}, {0, 1}});
	EXPECT_EQ(g.layers.getHeight(0), 1);
	EXPECT_EQ(g.layers.getHeight(1), 2);
}

TEST(StackLayers, JointEdgeIsSolvedInTheLayerOfItsEdge)
{
	// 0 on the ground, a joint (edge 2) hangs 2 from 1, 1 rests on 0.
	Graph g(3, {{R, 0}, {0, 1}, {1, 2}});
	EXPECT_EQ(g.layers.getEdgeLayer(2), 2);
	EXPECT_EQ(g.fixatedBodies(2), std::set<int>({1}));
}

// The door of docs/design.md (D12): left column 0-1, right column 2-3-4-5, lintel 6 on 1 and 5.
// Every edge is a support edge: the first body rests on the second.
namespace
{
const std::vector<std::pair<int, int>> kDoorEdges{{0, R}, {1, 0}, {2, R}, {3, 2}, {4, 3}, {5, 4}, {6, 1}, {6, 5}};
const std::vector<int> kDoorSupports(kDoorEdges.size(), BT_SUPPORT_A_ON_B);
}  // namespace

TEST(StackLayers, BfsAloneClampsTheDoorsRightTopBoxBetweenTwoFixatedBodies)
{
	// Without support information: the lintel gets BFS height 3 and is fixated in the layer where
	// the right column's top box (height 4) is free, below it.
	Graph g(7, kDoorEdges);
	EXPECT_EQ(g.layers.getHeight(6), 3);
	EXPECT_EQ(g.layers.getHeight(5), 4);
	EXPECT_EQ(g.fixatedBodies(3), std::set<int>({4, 6}));
}

TEST(StackLayers, SupportOrderingPutsTheDoorLintelAboveBothColumns)
{
	Graph g(7, kDoorEdges, kDoorSupports);
	EXPECT_EQ(g.layers.getHeight(1), 2);
	EXPECT_EQ(g.layers.getHeight(5), 4);
	EXPECT_EQ(g.layers.getHeight(6), 5) << "lintel one above the taller column";
	ASSERT_EQ(g.layers.getNumLayers(), 5);
	// The lintel is free in layer 4 with both column tops fixated: both supports in one solve.
	EXPECT_EQ(g.freeBodies(4), std::set<int>({6}));
	EXPECT_EQ(g.fixatedBodies(4), std::set<int>({1, 5}));
	EXPECT_EQ(g.layers.getEdgeLayer(6), 4);
	EXPECT_EQ(g.layers.getEdgeLayer(7), 4);
	// No layer fixates a body that rests on one of the layer's free bodies.
	for (int k = 0; k < g.layers.getNumLayers(); ++k)
		for (int e = 0; e < g.graph.getNumEdges(); ++e)
			if (g.layers.getEdgeLayer(e) == k && kDoorEdges[e].second >= 0)
			{
				EXPECT_EQ(g.fixatedBodies(k).count(kDoorEdges[e].first), 0u) << "layer " << k << " edge " << e;
			}
}

TEST(StackLayers, SideContactsDoNotRaiseHeights)
{
	// Two boxes on the ground side by side, a third resting on the first only.
	Graph g(3, {{0, R}, {1, R}, {0, 1}, {2, 0}}, {BT_SUPPORT_A_ON_B, BT_SUPPORT_A_ON_B, BT_SUPPORT_NONE, BT_SUPPORT_A_ON_B});
	EXPECT_EQ(g.layers.getHeight(0), 1);
	EXPECT_EQ(g.layers.getHeight(1), 1);
	EXPECT_EQ(g.layers.getHeight(2), 2);
	EXPECT_EQ(g.layers.getEdgeLayer(2), 0) << "side contact: both free in layer 0";
}

TEST(StackLayers, SupportCycleKeepsFiniteHeightsAndEveryBodyFreeOnce)
{
	// 0 on the ground; 1, 2, 3 each "rest on" the next in a cycle (tilted contacts can do this).
	Graph g(4, {{0, R}, {1, 0}, {1, 2}, {2, 3}, {3, 1}}, {BT_SUPPORT_A_ON_B, BT_SUPPORT_A_ON_B, BT_SUPPORT_A_ON_B, BT_SUPPORT_A_ON_B, BT_SUPPORT_A_ON_B});
	int freeCount = 0;
	for (int k = 0; k < g.layers.getNumLayers(); ++k) freeCount += g.layers.getNumFreeBodies(k);
	EXPECT_EQ(freeCount, 4);
	for (int b = 0; b < 4; ++b)
	{
		EXPECT_GE(g.layers.getHeight(b), 1);
		EXPECT_LE(g.layers.getHeight(b), 4);
	}
}

TEST(StackLayers, RootRootEdgeIsIgnored)
{
	btContactGraph graph;
	graph.reset(1);
	EXPECT_EQ(graph.addEdge(R, R, 0), -1);
	EXPECT_EQ(graph.getNumEdges(), 0);
}

TEST(StackLayers, EmptyGraphHasNoLayers)
{
	Graph g(0, {});
	EXPECT_EQ(g.layers.getNumLayers(), 0);
	EXPECT_EQ(g.layers.getNumComponents(), 0);
	EXPECT_EQ(g.layers.getLargestLayer(), 0);
}

// Naive reference: Bellman-Ford style relaxation until nothing changes.
std::vector<int> referenceHeights(int n, const std::vector<std::pair<int, int>>& edges)
{
	const int inf = 1 << 29;
	std::vector<int> h(n, inf);
	for (auto e : edges)
	{
		if (e.first == R && e.second != R) h[e.second] = 1;
		if (e.second == R && e.first != R) h[e.first] = 1;
	}
	for (bool changed = true; changed;)
	{
		changed = false;
		for (auto e : edges)
		{
			if (e.first == R || e.second == R) continue;
			if (h[e.first] + 1 < h[e.second]) h[e.second] = h[e.first] + 1, changed = true;
			if (h[e.second] + 1 < h[e.first]) h[e.first] = h[e.second] + 1, changed = true;
		}
	}
	for (int& x : h)
		if (x == inf) x = BT_STACK_HEIGHT_UNREACHED;
	return h;
}

TEST(StackLayers, RandomizedDifferentialAgainstNaiveReference)
{
	std::mt19937 rng(12345);
	for (int trial = 0; trial < 2000; ++trial)
	{
		const int n = 1 + int(rng() % 40);
		const int m = int(rng() % (3 * n));
		std::vector<std::pair<int, int>> edges;
		for (int i = 0; i < m; ++i)
		{
			int a = int(rng() % (n + 1)) - 1, b = int(rng() % (n + 1)) - 1;
			if (a == R && b == R) b = 0;
			edges.push_back({a, b});
		}
		Graph g(n, edges);
		const std::vector<int> ref = referenceHeights(n, edges);
		int maxLayer = 0;
		for (int b = 0; b < n; ++b)
		{
			ASSERT_EQ(g.layers.getHeight(b), ref[b]) << "trial " << trial << " body " << b;
			maxLayer = std::max(maxLayer, ref[b] == BT_STACK_HEIGHT_UNREACHED ? 0 : ref[b] - 1);
		}
		ASSERT_EQ(g.layers.getNumLayers(), maxLayer + 1);
		// Every body is free in exactly one layer; every edge in exactly one layer.
		std::vector<int> freeCount(n, 0);
		int edgeCount = 0;
		for (int k = 0; k < g.layers.getNumLayers(); ++k)
		{
			for (int i = 0; i < g.layers.getNumFreeBodies(k); ++i) ++freeCount[g.layers.getFreeBody(k, i)];
			edgeCount += g.layers.getNumLayerEdges(k);
			// Fixated bodies of layer k have height k and are never free in k.
			for (int i = 0; i < g.layers.getNumFixatedBodies(k); ++i)
				ASSERT_EQ(g.layers.getHeight(g.layers.getFixatedBody(k, i)), k);
		}
		for (int b = 0; b < n; ++b) ASSERT_EQ(freeCount[b], 1);
		ASSERT_EQ(edgeCount, g.graph.getNumEdges());
		// Every edge connects only free bodies of its layer and fixated ones (or roots).
		for (int e = 0; e < g.graph.getNumEdges(); ++e)
		{
			const int k = g.layers.getEdgeLayer(e);
			const btContactGraphEdge& edge = g.graph.getEdge(e);
			for (int end : {edge.m_bodyA, edge.m_bodyB})
			{
				if (end == R) continue;
				const int h = g.layers.getHeight(end);
				ASSERT_TRUE(h == BT_STACK_HEIGHT_UNREACHED ? k == 0 : (h == k + 1 || h == k)) << "trial " << trial;
			}
		}
	}
}
