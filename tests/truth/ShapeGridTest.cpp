// The shape grid (issue 37), first slice: a column of 10 equal bodies (1 m wide, 0.5 m tall, 1 kg,
// mu 0.6) of one shape on one kind of ground (demos/scenes/src/ShapeKinds.cpp) is in equilibrium, so
// it must stand: every body within 1 cm of its start for 10 s. Asserted for the plugin's defaults at
// 10 iterations, world and solver-only mode, on every cell of shapes x grounds; in the same test the
// converged reference (stock SI, 8 sub-steps x 100 iterations) runs, and a cell it does not hold
// (within 1.5 cm: it creeps 1.4 cm on a plane) is skipped, so a cell is asserted only where physics
// and the reference agree. docs/design.md D33 has the figures.
#include <truth/GridCases.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

namespace
{
/// A structure in equilibrium (a cell of `shape` on `ground`, the statement `verdict`) stands in
/// world and solver-only mode at 10 iterations, where the converged reference (stock SI, 8
/// sub-steps x 100 iterations, run here) holds it; stock SI at 10 iterations is printed beside.
using Verdict = truth::Verdict (*)(const harness::SolverSpec&, int, int);

void expectStands(const char* what, Verdict verdict, int shape, int ground)
{
	auto run = [&](harness::SolverKind kind, int iterations, int substeps) {
		harness::SolverSpec spec;
		spec.kind = kind;
		spec.iterations = iterations;
		spec.substeps = substeps;
		return verdict(spec, shape, ground);
	};
	const truth::Verdict reference = run(harness::SolverKind::StockSI, 100, 8);
	const truth::Verdict world = run(harness::SolverKind::ShockWorld, 10, 1);
	const truth::Verdict solver = run(harness::SolverKind::ShockSolverOnly, 10, 1);
	const truth::Verdict stock = run(harness::SolverKind::StockSI, 10, 1);
	std::printf("GRID | %s shape %d ground %d | reference %.4f m, world %.4f m, solver-only %.4f m, stock SI 10 %.4f m\n", what, shape,
				ground, reference.figure, world.figure, solver.figure, stock.figure);
	// Where the converged reference loses the structure too, the cell is no truth (double
	// precision's heightfield ground under a column: 0.3-358 m, not traced).
	if (!(reference.figure < 0.015) || reference.detail.find("non-finite") != std::string::npos)
		GTEST_SKIP() << "the reference does not hold this cell: " << reference.detail;
	EXPECT_TRUE(world.pass) << "plugin world, shape " << shape << " ground " << ground << ": " << world.detail;
	EXPECT_TRUE(solver.pass) << "plugin solver-only, shape " << shape << " ground " << ground << ": " << solver.detail;
}

const char* kGroundNames[] = {"onBox", "onPlane", "onMesh", "onMeshEdges", "onHeightfield"};

class ColumnStands : public ::testing::TestWithParam<std::tuple<int, int>>
{
};

TEST_P(ColumnStands, WorldAndSolverOnly) { expectStands("shape_column", truth::columnStandsVerdict, std::get<0>(GetParam()), std::get<1>(GetParam())); }

std::string cellName(const ::testing::TestParamInfo<std::tuple<int, int>>& info)
{
	static const char* shapes[] = {"box", "hull", "hullFeatures", "prism", "cylinder", "compound"};
	return std::string(shapes[std::get<0>(info.param)]) + "_" + kGroundNames[std::get<1>(info.param)];
}

INSTANTIATE_TEST_SUITE_P(Grid, ColumnStands,
						 ::testing::Combine(::testing::Values(0, 1, 3, 4, 5), ::testing::Values(0, 1, 2, 3, 4)),
						 cellName);

// Structures in equilibrium, each asserted like the columns (world and solver-only at 10
// iterations, the converged reference in the same test; a cell it does not hold is skipped):
// - a 100 kg round body (a sphere, or a capsule on its side; radius 0.25 m) on the middle of a 1 kg
//   box: the ball's single point does not fix its turn, and its rows were solved as plain
//   Gauss-Seidel at 100:1 (btGroundedFixation.cpp, a body that carries its own load); the capsule's
//   points, fixed in the capsule, lagged beside its line once it rolled (D33, touching segment);
// - a 10 kg table made as one compound body (top and four legs) carrying 5 boxes;
// - a crib of 10 layers of two interlocking planks, boxes or hulls: two hull planks cross in a
//   square whose corners are no rim point of either (D33, crossings of the rims' edges).
class RoundOnBlock : public ::testing::TestWithParam<std::tuple<int, int>>
{
};

TEST_P(RoundOnBlock, WorldAndSolverOnly) { expectStands("round_on_block", truth::roundOnBlockVerdict, std::get<0>(GetParam()), std::get<1>(GetParam())); }

INSTANTIATE_TEST_SUITE_P(Grid, RoundOnBlock, ::testing::Combine(::testing::Values(6, 7), ::testing::Values(0, 1, 2, 3, 4)),
						 [](const ::testing::TestParamInfo<std::tuple<int, int>>& info) {
							 return std::string(std::get<0>(info.param) == 6 ? "capsule" : "sphere") + "_" + kGroundNames[std::get<1>(info.param)];
						 });

class TableStack : public ::testing::TestWithParam<int>
{
};

truth::Verdict tableVerdict(const harness::SolverSpec& spec, int, int ground) { return truth::tableStackVerdict(spec, ground); }

TEST_P(TableStack, WorldAndSolverOnly) { expectStands("table_stack", tableVerdict, 0, GetParam()); }

INSTANTIATE_TEST_SUITE_P(Grid, TableStack, ::testing::Values(0, 1, 2, 3, 4),
						 [](const ::testing::TestParamInfo<int>& info) { return std::string(kGroundNames[info.param]); });

// What must fall is asserted as hard: the same table with its column 1 m off the middle, its centre
// of mass beyond the top's edge (0.8 m), must lose it over the edge within 3 s. Stock SI at 10
// iterations runs beside it, and the reference's verdict decides the cell as above.
class TableStackOffTheEdge : public ::testing::TestWithParam<int>
{
};

TEST_P(TableStackOffTheEdge, FallsInWorldAndSolverOnly)
{
	const int ground = GetParam();
	auto run = [&](harness::SolverKind kind, int iterations, int substeps) {
		harness::SolverSpec spec;
		spec.kind = kind;
		spec.iterations = iterations;
		spec.substeps = substeps;
		return truth::tableStackFallsVerdict(spec, ground);
	};
	const truth::Verdict reference = run(harness::SolverKind::StockSI, 100, 8);
	const truth::Verdict world = run(harness::SolverKind::ShockWorld, 10, 1);
	const truth::Verdict solver = run(harness::SolverKind::ShockSolverOnly, 10, 1);
	std::printf("GRID | table_stack off the edge ground %d | top box above the table top after 3 s: reference %.3f m, world %.3f m, "
				"solver-only %.3f m\n",
				ground, reference.figure, world.figure, solver.figure);
	if (!reference.pass) GTEST_SKIP() << "the reference does not hold this cell: " << reference.detail;
	EXPECT_TRUE(world.pass) << "plugin world: " << world.detail;
	EXPECT_TRUE(solver.pass) << "plugin solver-only: " << solver.detail;
}

INSTANTIATE_TEST_SUITE_P(Grid, TableStackOffTheEdge, ::testing::Values(0, 1, 2, 3, 4),
						 [](const ::testing::TestParamInfo<int>& info) { return std::string(kGroundNames[info.param]); });

class PlankCrib : public ::testing::TestWithParam<std::tuple<int, int>>
{
};

TEST_P(PlankCrib, WorldAndSolverOnly) { expectStands("plank_crib", truth::plankCribVerdict, std::get<0>(GetParam()), std::get<1>(GetParam())); }

INSTANTIATE_TEST_SUITE_P(Grid, PlankCrib, ::testing::Combine(::testing::Values(0, 1), ::testing::Values(0, 1, 2, 3, 4)),
						 [](const ::testing::TestParamInfo<std::tuple<int, int>>& info) {
							 return std::string(std::get<0>(info.param) == 0 ? "box" : "hull") + "_" + kGroundNames[std::get<1>(info.param)];
						 });

// Not in the grid: the hull with polyhedral features (shape 2), which the converged reference does
// not hold (3.3-6.1 cm in float: Bullet's clipping of two hulls' bare faces moves the column while
// its contacts settle; the plugin 0.0-1.4 cm).
}  // namespace
