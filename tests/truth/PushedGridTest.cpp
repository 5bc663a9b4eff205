// The shape grid (issue 37), the pushed stack: the truth case PushedStack (5 bodies of 1 kg stacked on
// the ground, box-ground mu 0.5, box-box mu 1, pushed at the bottom body with a fraction of mu W) built
// from every shape with a flat top and bottom on every kind of ground (demos/scenes/src/ShapeKinds.cpp).
// Coulomb does not care about the shape: pushed with 1.4 mu W the stack slides as one body at
// (F - mu W) / M (the acceleration within the truth case's 10%, no body more than 1 cm from where the
// bottom one carries it); pushed with 0.6 mu W it stays at rest (no body drifts 1 cm). Hexagonal prisms
// and cylinders differ from boxes in inertia and contact geometry, not in that statement.
// Asserted for the plugin's defaults at 10 iterations, world and solver-only mode, on the cells where
// both hold today; in the same test the converged reference (stock SI, 8 sub-steps x 100 iterations)
// must hold the statement too, so a cell is asserted only where physics and the reference agree. Stock
// SI at 10 iterations is printed beside them, never asserted. The cells that do not hold yet are
// DISABLED_ specs below (run with --gtest_also_run_disabled_tests).
#include <truth/TruthCase.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace
{
struct Cell
{
	int shape;        ///< 0 box, 1 hull, 3 hexagonal prism, 4 cylinder, 5 compound
	int ground;       ///< 0 box, 1 plane, 2 mesh, 3 mesh + internal edges, 4 heightfield
	double fraction;  ///< the push in units of mu W: 1.4 slides, 0.6 stays
};

bool slides(const Cell& cell) { return cell.fraction > 1; }

/// The cell's physics statement, as the truth case PushedStack states it (truth::pushedStackVerdict).
truth::Verdict measure(harness::SolverKind kind, int iterations, int substeps, const Cell& cell)
{
	harness::SolverSpec spec;
	spec.kind = kind;
	spec.iterations = iterations;
	spec.substeps = substeps;
	return truth::pushedStackVerdict(spec, cell.fraction, {{"shape", cell.shape}, {"ground", cell.ground}});
}

std::string figures(const truth::Verdict& v) { return v.detail + (v.pass ? " holds" : " FAILS"); }

void expectCoulomb(const Cell& cell)
{
	const truth::Verdict reference = measure(harness::SolverKind::StockSI, 100, 8, cell);
	const truth::Verdict stock = measure(harness::SolverKind::StockSI, 10, 1, cell);
	const truth::Verdict world = measure(harness::SolverKind::ShockWorld, 10, 1, cell);
	const truth::Verdict solver = measure(harness::SolverKind::ShockSolverOnly, 10, 1, cell);
	std::printf("GRID | pushed_stack shape %d ground %d F %.1f mu W (%s) | reference: %s | stock SI 10: %s | world: %s | solver-only: %s\n",
				cell.shape, cell.ground, cell.fraction, slides(cell) ? "slides" : "stays", figures(reference).c_str(), figures(stock).c_str(),
				figures(world).c_str(), figures(solver).c_str());
	std::fflush(stdout);
	if (!reference.pass) GTEST_SKIP() << "the reference does not hold this cell: " << figures(reference);
	EXPECT_TRUE(world.pass) << "plugin world, shape " << cell.shape << " ground " << cell.ground << ": " << figures(world);
	EXPECT_TRUE(solver.pass) << "plugin solver-only, shape " << cell.shape << " ground " << cell.ground << ": " << figures(solver);
}

class PushedStackCoulomb : public ::testing::TestWithParam<Cell>
{
};

TEST_P(PushedStackCoulomb, WorldAndSolverOnly) { expectCoulomb(GetParam()); }

std::string cellName(const ::testing::TestParamInfo<Cell>& info)
{
	static const char* shapes[] = {"box", "hull", "hullFeatures", "prism", "cylinder", "compound"};
	static const char* grounds[] = {"onBox", "onPlane", "onMesh", "onMeshEdges", "onHeightfield"};
	return std::string(shapes[info.param.shape]) + "_" + grounds[info.param.ground] + (slides(info.param) ? "_F140_slides" : "_F060_stays");
}

constexpr double kSlides = 1.4, kStays = 0.6;

// Holding in float (Release): world and solver-only mode both hold the statement. Where the reference
// does not, the cell is skipped with the reference's figure: box, hull and prism on the plane sliding
// (reference apart 7.3, 6.3 and 5.3 cm), the compound on a box sliding (1.3 cm), the prism on a box at
// rest (drift 1.4 cm); the plugin holds all five (apart 0.0-2.8 mm, drift 0). Closest to its bound:
// the compound on the mesh with internal edges sliding, apart 8.6 mm in both modes.
INSTANTIATE_TEST_SUITE_P(Holding, PushedStackCoulomb,
						 ::testing::Values(Cell{0, 0, kSlides}, Cell{0, 1, kSlides}, Cell{1, 1, kSlides}, Cell{3, 1, kSlides}, Cell{4, 1, kSlides},
										   Cell{5, 0, kSlides}, Cell{5, 3, kSlides}, Cell{1, 3, kSlides}, Cell{3, 3, kSlides}, Cell{4, 3, kSlides},
										   Cell{5, 1, kSlides}, Cell{5, 4, kSlides},
										   Cell{0, 0, kStays}, Cell{0, 1, kStays}, Cell{0, 2, kStays}, Cell{0, 3, kStays}, Cell{0, 4, kStays},
										   Cell{1, 0, kStays}, Cell{1, 1, kStays}, Cell{1, 2, kStays}, Cell{1, 3, kStays}, Cell{1, 4, kStays},
										   Cell{3, 0, kStays}, Cell{3, 1, kStays}, Cell{3, 2, kStays}, Cell{3, 3, kStays}, Cell{3, 4, kStays},
										   Cell{4, 0, kStays}, Cell{4, 1, kStays}, Cell{4, 2, kStays}, Cell{4, 3, kStays}, Cell{4, 4, kStays},
										   Cell{5, 0, kStays}, Cell{5, 1, kStays}, Cell{5, 2, kStays}, Cell{5, 3, kStays}, Cell{5, 4, kStays}),
						 cellName);

// Not holding yet: sliding cells where world or solver-only mode fails (float, the last run, with
// D33's triangles under the patch; a against Coulomb's 1.962 m/s^2, apart in m; world / solver-only).
// In every one of them the converged reference fails too, so none would be asserted today (its upper
// bodies creep back 3-32 cm relative to the bottom one over the 2 s; on the mesh without Bullet's
// internal-edge adjustment and the heightfield the bottom body also catches on cell edges and a falls
// short), but a build whose reference holds would assert them:
//   box on mesh             a 1.954 / 1.941, apart 0.0059 / 0.0180
//   box on mesh+edges       apart 0.0105 / 0.0075
//   box on heightfield      a 1.765 / 2.501, apart 0.702 / 1.45
//   hull on box             apart 0.0115 / 0.0041
//   hull on mesh            a 1.575 / 1.561, apart 0.188 / 0.0175
//   hull on heightfield     a 1.400 / 1.612, apart 0.145 / 0.154
//   prism on box            apart 0.0170 / 0.0185
//   prism on mesh           a 1.779 / 1.820, apart 0.239 / 0.0485
//   prism on heightfield    a 1.575 / 1.469, apart 0.280 / 0.113
//   cylinder on box         apart 0.0783 / 0.0637
//   cylinder on mesh        a 1.450 / 1.107, apart 0.292 / 0.235
//   cylinder on heightfield a 1.502 / 1.532, apart 0.260 / 0.238
//   compound on mesh        a 1.354 / 1.691, apart 0.187 / 0.0711
INSTANTIATE_TEST_SUITE_P(DISABLED_NotYet, PushedStackCoulomb,
						 ::testing::Values(Cell{0, 2, kSlides}, Cell{0, 3, kSlides}, Cell{0, 4, kSlides},
										   Cell{1, 0, kSlides}, Cell{1, 2, kSlides}, Cell{1, 4, kSlides},
										   Cell{3, 0, kSlides}, Cell{3, 2, kSlides}, Cell{3, 4, kSlides},
										   Cell{4, 0, kSlides}, Cell{4, 2, kSlides}, Cell{4, 4, kSlides},
										   Cell{5, 2, kSlides}),
						 cellName);
}  // namespace
