// The shape grid (issue 37), first slice: a column of 10 equal bodies (1 m wide, 0.5 m tall, 1 kg,
// mu 0.6) of one shape on one kind of ground (demos/scenes/src/ShapeKinds.cpp) is in equilibrium, so
// it must stand: every body within 1 cm of its start for 10 s. Asserted for the plugin's defaults at
// 10 iterations, world and solver-only mode, on the cells where both hold today; in the same test the
// converged reference (stock SI, 8 sub-steps x 100 iterations) must stand too, so a cell is asserted
// only where physics and the reference agree. The cells that do not hold yet are DISABLED_ specs
// below (run with --gtest_also_run_disabled_tests); docs/design.md D33 lists the figures.
#include <harness/Trial.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace
{
struct Cell
{
	int shape;   ///< 0 box, 1 hull, 3 hexagonal prism, 4 cylinder, 5 compound
	int ground;  ///< 0 box, 1 plane, 2 mesh, 3 mesh + internal edges, 4 heightfield
};

double columnDrift(harness::SolverKind kind, int iterations, int substeps, const Cell& cell)
{
	harness::SolverSpec spec;
	spec.kind = kind;
	spec.iterations = iterations;
	spec.substeps = substeps;
	harness::Trial trial(spec, "shape_column", {{"shape", cell.shape}, {"ground", cell.ground}});
	for (int k = 0; k < 600; ++k) trial.step();
	const harness::TrialSummary s = trial.summary();
	return s.nonFinite ? 1e9 : s.maxDrift;
}

void expectColumnStands(const Cell& cell)
{
	const double reference = columnDrift(harness::SolverKind::StockSI, 100, 8, cell);
	const double world = columnDrift(harness::SolverKind::ShockWorld, 10, 1, cell);
	const double solver = columnDrift(harness::SolverKind::ShockSolverOnly, 10, 1, cell);
	const double stock = columnDrift(harness::SolverKind::StockSI, 10, 1, cell);
	std::printf("GRID | shape_column shape %d ground %d | reference %.4f m, world %.4f m, solver-only %.4f m, stock SI 10 %.4f m\n",
				cell.shape, cell.ground, reference, world, solver, stock);
	// Where the converged reference loses the column too, the cell is no truth (double precision's
	// heightfield ground: 0.3-358 m, not traced).
	if (!(reference < 0.015)) GTEST_SKIP() << "the reference does not hold this cell: " << reference << " m";
	EXPECT_LT(world, 0.01) << "plugin world, shape " << cell.shape << " ground " << cell.ground;
	EXPECT_LT(solver, 0.01) << "plugin solver-only, shape " << cell.shape << " ground " << cell.ground;
}

class ColumnStands : public ::testing::TestWithParam<Cell>
{
};

TEST_P(ColumnStands, WorldAndSolverOnly) { expectColumnStands(GetParam()); }

std::string cellName(const ::testing::TestParamInfo<Cell>& info)
{
	static const char* shapes[] = {"box", "hull", "hullFeatures", "prism", "cylinder", "compound"};
	static const char* grounds[] = {"onBox", "onPlane", "onMesh", "onMeshEdges", "onHeightfield"};
	return std::string(shapes[info.param.shape]) + "_" + grounds[info.param.ground];
}

INSTANTIATE_TEST_SUITE_P(Holding, ColumnStands,
						 ::testing::Values(Cell{0, 0}, Cell{0, 1}, Cell{0, 2}, Cell{0, 3}, Cell{0, 4},  // boxes
										   Cell{1, 1}, Cell{1, 2}, Cell{1, 4},                         // hulls of a box's corners
										   Cell{5, 0}, Cell{5, 2}, Cell{5, 3}, Cell{5, 4}),             // compounds
						 cellName);

// Not holding yet (figures of the last run in docs/design.md D33): the hull on a box ground and on
// the mesh with internal edges, the prisms on every ground, cylinders on every ground (the world
// mode's correction loses them; solver-only mode drifts 1.2-4 cm), compounds on a plane (double
// precision's world mode 1.5 cm).
INSTANTIATE_TEST_SUITE_P(DISABLED_NotYet, ColumnStands,
						 ::testing::Values(Cell{1, 0}, Cell{1, 3}, Cell{3, 0}, Cell{3, 1}, Cell{3, 2}, Cell{3, 3}, Cell{3, 4}, Cell{5, 1},
										   Cell{4, 0}, Cell{4, 1}, Cell{4, 2}, Cell{4, 3}, Cell{4, 4}),
						 cellName);
}  // namespace
