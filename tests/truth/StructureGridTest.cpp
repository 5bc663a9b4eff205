// Structures that stand by friction alone (issue 37): a plank leaning at 60 degrees against a static
// wall (scene leaning_plank), friction mu at the floor and the wall, on every kind of ground. Statics
// gives the critical mu for the plank's geometry (the scene's fact "criticalMu", 0.245 here; Coulomb's
// ladder for a thin one): at 1.1 times it the plank stands (within 1 cm for 3 s), at 0.9 times it
// slides (its centre drops more than 10 cm within 3 s). The converged reference (stock SI, 8 sub-steps
// x 100 iterations) runs in the same test; a cell it gets wrong is skipped.
//
// The plank touches only static bodies, so its group has no stacked layer and the plugin's default
// hands it to Bullet's own solver (docs/design.md, section 9: flat groups are stock's bit for bit,
// tests/parity/DropInParityTest.cpp), which at 10 iterations lets it slide where it must stand
// (9-101 cm). The converging step (btShockPropagationDiagnostics::m_layerFlatGroups) holds it at
// 1.1 times the critical mu and lets it slide at 0.9 times: asserted here. The default's standing
// cells are a DISABLED_ spec: holding them by default means not handing such groups to stock, which
// the flat-group parity forbids today (docs/design.md, section 12).
#include <harness/Trial.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <tuple>

namespace
{
struct Outcome
{
	double drift = 0;  ///< m, largest displacement of the plank over the run
	double drop = 0;   ///< m, largest drop of its centre
	bool nonFinite = false;
};

Outcome runPlank(harness::SolverKind kind, int iterations, int substeps, bool layerFlat, int ground, double muFactor, double& criticalMu,
				 bool appTwoFrictionDirections = false)
{
	harness::SolverSpec spec;
	spec.kind = kind;
	spec.iterations = iterations;
	spec.substeps = substeps;
	spec.settings.m_diagnostics.m_layerFlatGroups = layerFlat;
	double critical = 0;
	{
		// The critical mu depends only on the geometry: read it from the scene at any mu.
		harness::Trial probe(spec, "leaning_plank", {{"ground", ground}});
		critical = probe.scene().facts.at("criticalMu");
	}
	criticalMu = critical;
	harness::Trial trial(spec, "leaning_plank", {{"ground", ground}, {"mu", muFactor * critical}});
	// The app's friction model: Bullet's one velocity-aligned row per point, or two (a pyramid).
	if (appTwoFrictionDirections) trial.simulation().world().getSolverInfo().m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
	const btRigidBody* plank = trial.scene().named("plank");
	const double startY = plank->getCenterOfMassPosition().y();
	Outcome o;
	for (int k = 0; k < 180; ++k)
	{
		trial.step();
		o.drop = std::max(o.drop, startY - double(plank->getCenterOfMassPosition().y()));
	}
	const harness::TrialSummary s = trial.summary();
	o.drift = s.maxDrift;
	o.nonFinite = s.nonFinite;
	return o;
}

bool holds(const Outcome& o, bool stands) { return !o.nonFinite && (stands ? o.drift < 0.01 : o.drop > 0.1); }

// appTwoRows: the app sets SOLVER_USE_2_FRICTION_DIRECTIONS. The app's friction model decides the
// default's flat groups (they are Bullet's own solve with the app's settings): with the two rows the
// default holds the plank at 1.1 times the critical mu and lets it slide at 0.9 times, on every
// ground where the reference does. With Bullet's default one friction row per point, stock slides at
// any iteration count on the plane and the mesh (printed then: stock SI at 200 iterations, one row),
// while stock with the two rows holds it at 10: the plank's slide is the one-row friction model's,
// not a solve that stopped early (docs/design.md, section 12).
void expectPlank(int ground, double muFactor, bool layerFlat, bool appTwoRows = false)
{
	const bool stands = muFactor > 1;
	double critical = 0;
	const Outcome reference = runPlank(harness::SolverKind::StockSI, 100, 8, false, ground, muFactor, critical);
	const Outcome world = runPlank(harness::SolverKind::ShockWorld, 10, 1, layerFlat, ground, muFactor, critical, appTwoRows);
	const Outcome solver = runPlank(harness::SolverKind::ShockSolverOnly, 10, 1, layerFlat, ground, muFactor, critical, appTwoRows);
	const Outcome stock = runPlank(harness::SolverKind::StockSI, 10, 1, false, ground, muFactor, critical, appTwoRows);
	std::printf("GRID | leaning_plank ground %d mu %.3f (%.1f x critical %.4f, %s)%s%s | reference drift %.4f drop %.3f | "
				"world %.4f / %.3f | solver-only %.4f / %.3f | stock SI 10 %.4f / %.3f m",
				ground, muFactor * critical, muFactor, critical, stands ? "stands" : "slides", layerFlat ? " flat groups layered" : "",
				appTwoRows ? ", app's two friction rows" : "", reference.drift, reference.drop, world.drift, world.drop, solver.drift, solver.drop,
				stock.drift, stock.drop);
	if (appTwoRows)
	{
		const Outcome oneRow = runPlank(harness::SolverKind::StockSI, 200, 1, false, ground, muFactor, critical);
		std::printf(" | stock SI 200, one row %.4f / %.3f m", oneRow.drift, oneRow.drop);
	}
	std::printf("\n");
	if (!holds(reference, stands)) GTEST_SKIP() << "the reference does not hold this cell";
	EXPECT_TRUE(holds(world, stands)) << "world: drift " << world.drift << " m, drop " << world.drop << " m";
	EXPECT_TRUE(holds(solver, stands)) << "solver-only: drift " << solver.drift << " m, drop " << solver.drop << " m";
}

class LeaningPlank : public ::testing::TestWithParam<std::tuple<int, double>>
{
};

TEST_P(LeaningPlank, ConvergingStepStandsOrSlidesAsStaticsSays) { expectPlank(std::get<0>(GetParam()), std::get<1>(GetParam()), true); }

class LeaningPlankDefault : public LeaningPlank
{
};

TEST_P(LeaningPlankDefault, StandsOrSlidesAsStaticsSays) { expectPlank(std::get<0>(GetParam()), std::get<1>(GetParam()), false); }

class LeaningPlankAppFriction : public LeaningPlank
{
};

TEST_P(LeaningPlankAppFriction, StandsOrSlidesAsStaticsSays) { expectPlank(std::get<0>(GetParam()), std::get<1>(GetParam()), false, true); }

std::string cellName(const ::testing::TestParamInfo<std::tuple<int, double>>& info)
{
	static const char* grounds[] = {"onBox", "onPlane", "onMesh", "onMeshEdges", "onHeightfield"};
	return std::string(grounds[std::get<0>(info.param)]) + (std::get<1>(info.param) > 1 ? "_stands" : "_slides");
}

INSTANTIATE_TEST_SUITE_P(Grid, LeaningPlank,
						 ::testing::Values(std::make_tuple(0, 1.1), std::make_tuple(1, 1.1), std::make_tuple(2, 1.1), std::make_tuple(3, 1.1),
										   std::make_tuple(4, 1.1), std::make_tuple(0, 0.9), std::make_tuple(1, 0.9), std::make_tuple(3, 0.9)),
						 cellName);
// Sliding on a mesh without Bullet's internal-edge adjustment and on a heightfield, the plank's
// lower edge (an edge on a face, which D33 does not touch) catches on an internal edge after 8 cm
// in every mode but the reference (float: the reference catches on the mesh too; double: it slides
// 84 cm on both).
INSTANTIATE_TEST_SUITE_P(DISABLED_NotYet, LeaningPlank, ::testing::Values(std::make_tuple(2, 0.9), std::make_tuple(4, 0.9)), cellName);
// The default slides where statics says so (stock's solve does too) ...
INSTANTIATE_TEST_SUITE_P(Grid, LeaningPlankDefault, ::testing::Combine(::testing::Values(0, 1, 3), ::testing::Values(0.9)), cellName);
// ... but lets the plank slide where it must stand (stock's 10 sweeps, 0.21-2.7 m): see the header;
// and on the heightfield (no internal-edge adjustment) the sliding plank's lower edge catches on a
// cell edge after 8.5 cm (the reference slides 84 cm; the converging step 10.5 cm), on the mesh
// without the adjustment likewise in double.
INSTANTIATE_TEST_SUITE_P(DISABLED_NotYet, LeaningPlankDefault,
						 ::testing::Values(std::make_tuple(0, 1.1), std::make_tuple(1, 1.1), std::make_tuple(2, 1.1), std::make_tuple(3, 1.1),
										   std::make_tuple(4, 1.1), std::make_tuple(2, 0.9), std::make_tuple(4, 0.9)),
						 cellName);
// With the app's two friction directions the default holds every standing cell the reference holds
// (the heightfield's standing cell the reference does not) and lets the plank slide on the grounds
// where its lower edge meets no internal edge (the unadjusted mesh and the heightfield: above).
INSTANTIATE_TEST_SUITE_P(Grid, LeaningPlankAppFriction,
						 ::testing::Values(std::make_tuple(0, 1.1), std::make_tuple(1, 1.1), std::make_tuple(2, 1.1), std::make_tuple(3, 1.1),
										   std::make_tuple(4, 1.1), std::make_tuple(0, 0.9), std::make_tuple(1, 0.9), std::make_tuple(3, 0.9)),
						 cellName);
}  // namespace
