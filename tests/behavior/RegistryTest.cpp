// Every registry scene, small instance, under every compared solver for 1 s: the scene builds and
// its bodies stay finite; under the plugin nothing is flung either (issue 3: the registry-wide spec).
#include "Fixture.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace
{
using Overrides = std::vector<std::pair<std::string, double>>;

/// Small instances of the large scenes (the registry defaults are benchmark sized).
Overrides smallInstance(const std::string& scene)
{
	if (scene == "pyramid") return {{"base", 6}};
	if (scene == "wall") return {{"rows", 4}, {"length", 5}};
	if (scene == "round_tower") return {{"rings", 3}, {"ring", 8}};
	if (scene == "dense_random") return {{"count", 20}};
	if (scene == "tower") return {{"n", 8}};
	if (scene == "card_house") return {{"levels", 2}};
	if (scene == "ragdoll_pile") return {{"columnsX", 1}, {"columnsZ", 1}, {"layers", 2}};
	if (scene == "leaning_columns") return {{"columnsX", 1}, {"columnsZ", 1}, {"layers", 6}};
	if (scene == "boxes_3000") return {{"columnsX", 2}, {"columnsZ", 1}, {"layers", 3}};
	if (scene == "stack_1000") return {{"pyramid", 2}, {"walls", 1}, {"wallRows", 2}, {"rings", 2}, {"ringCubes", 12}};
	if (scene == "flat_boxes") return {{"countX", 3}, {"countZ", 2}, {"v0", 2}};
	return {};
}

std::vector<std::string> allScenes()
{
	std::vector<std::string> names;
	for (const scenes::SceneEntry& e : scenes::registry()) names.push_back(e.name);
	return names;
}

const std::vector<std::string> kSolvers = {"si", "si2f", "nncg", "mlcp", "si-sub4", "sp", "sp-solver", "sp-classic"};

/// Fastest a body could move after 1 s from the scenes' own energy: a fall from the highest
/// start (under 12 m in every small instance) or the fastest initial speed (5 m/s), with margin.
const double kMaxPlausibleSpeed = 25.0;
}  // namespace

class RegistrySmoke : public ::testing::TestWithParam<std::tuple<std::string, std::string>>
{
};

TEST_P(RegistrySmoke, RunsOneSecondFiniteAndNothingFlung)
{
	const std::string& scene = std::get<0>(GetParam());
	// Measured: stock btNNCGConstraintSolver (Bullet 3.24) turns even one ragdoll of ragdoll_pile
	// (hinges and cone twists) non-finite within 1 s, at 10 and 50 iterations; SI, MLCP and the plugin
	// do not. A Bullet fact, reported by bsp_truth (RagdollPileCollapses), not a scene defect.
	if (scene == "ragdoll_pile" && std::get<1>(GetParam()) == "nncg") GTEST_SKIP() << "stock NNCG goes non-finite on ragdolls";
	harness::SolverSpec solver;
	std::string error;
	ASSERT_TRUE(harness::parseSolverKind(std::get<1>(GetParam()), solver, error)) << error;
	solver.iterations = 10;

	harness::Trial run(solver, scene, smallInstance(scene));
	ASSERT_NE(run.scene().ground(), nullptr);
	ASSERT_EQ(double(run.bodies().size()), run.scene().facts.at("bodies"));
	const int constraints = run.simulation().world().getNumConstraints();
	const int objects = run.simulation().world().getNumCollisionObjects();
	run.run(1.0);

	EXPECT_FALSE(harness::anyNonFinite(run.bodies()));
	EXPECT_EQ(run.simulation().world().getNumConstraints(), constraints);
	EXPECT_EQ(run.simulation().world().getNumCollisionObjects(), objects);
	// Bullet's own solvers are here for the no-NaN check only: stock NNCG, for one, flings the
	// 10 g cards of the card house. The plugin must keep every scene plausible.
	const bool plugin = solver.isPlugin();
	if (!plugin) return;
	for (const btRigidBody* b : run.bodies())
	{
		EXPECT_LT(b->getLinearVelocity().length(), kMaxPlausibleSpeed) << "a body of " << scene << " was flung";
		EXPECT_GT(b->getCenterOfMassPosition().y(), -1.0) << "a body of " << scene << " fell through the ground";
	}
}

INSTANTIATE_TEST_SUITE_P(Registry, RegistrySmoke, ::testing::Combine(::testing::ValuesIn(allScenes()), ::testing::ValuesIn(kSolvers)),
						 [](const ::testing::TestParamInfo<RegistrySmoke::ParamType>& info) {
							 std::string name = std::get<0>(info.param) + "_" + std::get<1>(info.param);
							 for (char& c : name)
								 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
							 return name;
						 });
