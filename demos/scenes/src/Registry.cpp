// The one table of every scene. Add a scene here and nowhere else; the demo, the tests and the
// benchmarks iterate over this table.

#include "scenes/Registry.h"

#include "SceneCatalog.h"

#include <ostream>
#include <stdexcept>

namespace scenes
{
const std::vector<SceneEntry>& registry()
{
	static const std::vector<SceneEntry> table = {
		// basic: one body, outcome known in closed form
		{"basic", "single_box", "One 1 x 0.5 x 1 m box resting on the ground: the smallest resting contact.", createSingleBox, singleBoxParams()},
		{"basic", "sliding_box", "A box launched along +x at v0 on the ground; Coulomb friction stops it after v0^2 / (2 mu g).", createSlidingBox, slidingBoxParams()},
		{"basic", "free_fall", "A box falling from h0 with no contact: pure ballistic motion.", createFreeFall, freeFallParams()},

		// seed: the source paper's presentation
		{"seed", "sparse_stacking", "Several separate short stacks of cubes in a row: many small independent islands.", createSparseStacking, sparseStackingParams()},
		{"seed", "dense_random", "Seeded random cubes dropped into a walled pit, settling into a compact pile.", createDenseRandom, denseRandomParams()},
		{"seed", "pyramid", "Dense structured stacking: a 2-D pyramid of boxes, base * (base + 1) / 2 bodies (base 140: 9,870).", createPyramid, pyramidParams()},
		{"seed", "wall", "Running-bond brick wall, 200 pieces in 16 rows with flush ends (half bricks); stock SI cannot hold it.", createWall, wallParams()},
		{"seed", "round_tower", "Round tower of 20 rings of 16 bricks, alternate rings turned by half a brick.", createRoundTower, roundTowerParams()},

		// hard: known failure modes of iterative solvers
		{"hard", "tower", "Tall vertical stack of 20 boxes, optionally offset alternately; stock SI lets it creep and fall.", createTower, towerParams()},
		{"hard", "mass_ratio_tower", "Four-box tower whose top box is 1000 times heavier than the rest.", createMassRatioTower, massRatioTowerParams()},
		{"hard", "large_on_small", "A heavy slab bridging two light cubes under its ends (mass ratio 100).", createLargeOnSmall, largeOnSmallParams()},
		{"hard", "seesaw", "Plank balanced on a static edge with a stack on its left end: it must tip left and carry the weight.", createSeesaw, seesawParams()},
		{"hard", "loaded_plank", "Plank on two thin posts with a heavy box off centre: the posts share the load by the lever rule.", createLoadedPlank, loadedPlankParams()},
		{"hard", "door", "Lintel on two columns of equal height made of 2 and 4 boxes (goal post).", createDoor, doorParams()},
		{"hard", "arch", "Semicircular arch of 17 wedge voussoirs on the ground; holds only through friction at every joint (hard case).", createArch, archParams()},
		{"hard", "card_house", "House of thin cards: leaning pairs form tents, flat cards carry the next level (hard case).", createCardHouse, cardHouseParams()},
		{"hard", "friction_ramp", "Cubes side by side on a 20 degree ramp, friction 0 to 0.75: those with mu < tan(angle) slide.", createFrictionRamp, frictionRampParams()},
		{"hard", "overlap_recovery", "Small pyramid started with every row sunk 25% of a cube into its support; must separate without flinging.", createOverlapRecovery, overlapRecoveryParams()},
		{"hard", "domino_row", "Row of 15 dominoes; the first is tipped and the chain reaction topples them all.", createDominoRow, dominoRowParams()},
		{"hard", "leaning_tower", "Cubes each shifted 0.3 of their edge past the one below: the centre of mass overhangs, so it topples.", createLeaningTower, leaningTowerParams()},
		{"hard", "hinge_bridge", "Planks chained by hinges between two posts, loaded with cubes; sags to an equilibrium and the joints hold.", createHingeBridge, hingeBridgeParams()},

		// truth: outcome predicted by statics or Coulomb friction in closed form (the truth suite, demos/truth)
		{"truth", "harmonic_stack", "Cubes with the book-stacking overhang a / (2k) times scale: stands iff scale <= 1.", createHarmonicStack, harmonicStackParams()},
		{"truth", "pushed_stack", "Five boxes stacked on the ground, box friction 1, ground friction 0.5: pushed at the bottom, slides iff F > mu W.", createPushedStack, pushedStackParams()},
		{"truth", "ledge_column", "Six aligned cubes on a static ledge, their axis 0.2 of an edge past its edge: the column tips about the edge as one rigid body.", createLedgeColumn, ledgeColumnParams()},
		{"truth", "ramp_stack", "Three boxes stacked on a 20 degree ramp: sticks iff mu >= tan(angle), else slides at g (sin a - mu cos a).", createRampStack, rampStackParams()},
		{"truth", "shape_column", "Column of 10 equal bodies of one shape (box, hull, prism, cylinder, compound) on a box, plane, mesh or heightfield ground: stands.", createShapeColumn, shapeColumnParams()},
		{"truth", "round_on_block", "A heavy sphere or lying capsule at rest on a light box on the ground (any ground kind): both stay at rest.", createRoundOnBlock, roundOnBlockParams()},
		{"truth", "leaning_plank", "A plank leaning at 60 degrees against a static wall on any ground kind: stands iff mu is above the critical mu statics gives for its geometry.", createLeaningPlank, leaningPlankParams()},
		{"truth", "table_stack", "A table made as one compound body (top and four legs) carrying a column of 5 boxes, on any ground kind: it stands.", createTableStack, tableStackParams()},
		{"truth", "plank_crib", "A crib of interlocking planks, 10 layers of two, each layer turned 90 degrees, on any ground kind: it stands.", createPlankCrib, plankCribParams()},
		{"truth", "hull_bin", "30 random convex hulls dropped into a walled bin on any ground kind: they settle into a pile that comes to rest.", createHullBin, hullBinParams()},
		{"truth", "loaded_lintel", "Lintel on two capped columns with a heavy box off centre: the caps share the load by the lever rule.", createLoadedLintel, loadedLintelParams()},

		// benchmark: layouts after Bullet's BenchmarkDemo and PyBullet's tests, with the outcome physics predicts
		{"benchmark", "leaning_columns", "BenchmarkDemo's \"3000 boxes\" staircases, 2 x 2 columns of 12: each layer 0.35 m further out, so every column topples.", createLeaningColumns, leaningColumnsParams()},
		{"benchmark", "ragdoll_pile", "BenchmarkDemo's passive ragdolls (11 capsules, hinges and cone twists), 2 x 2 x 3 dropped onto each other: they fold and fall.", createRagdollPile, ragdollPileParams()},
		{"benchmark", "heavy_top_column", "PyBullet's column of 10 unit cubes whose top cube is 1000 times heavier: it stands and gains no energy.", createHeavyTopColumn, heavyTopColumnParams()},
		{"benchmark", "stack_1000", "BenchmarkDemo's \"1000 stack\": a 12-layer cube pyramid, three 12-row walls and a round tower of 8 rings of 24 (1076 cubes); it stands.", createStack1000, stack1000Params()},
		{"benchmark", "boxes_3000", "BenchmarkDemo's \"3000 boxes\" at full size: 8 x 8 leaning columns of 47 cubes (3008) dropped in staircases that topple.", createBoxes3000, boxes3000Params()},
		{"benchmark", "basic_demo_block", "BasicDemo's 5 x 5 x 5 block of 0.2 m cubes dropped 1.9 m onto the ground: it lands flat and stays a block.", createBasicDemoBlock, basicDemoBlockParams()},
		{"benchmark", "flat_boxes", "Cost baseline without stacks: 20 x 20 cubes side by side on the ground, one layer, at rest or sliding at v0.", createFlatBoxes, flatBoxesParams()},
	};
	return table;
}

const SceneEntry* findScene(const std::string& name)
{
	for (const SceneEntry& entry : registry())
	{
		if (entry.name == name)
			return &entry;
	}
	return nullptr;
}

std::string sceneNames()
{
	std::string names;
	for (const SceneEntry& entry : registry())
	{
		if (!names.empty())
			names += ", ";
		names += entry.name;
	}
	return names;
}

std::unique_ptr<SceneContent> createScene(btDiscreteDynamicsWorld& world, const std::string& name,
										  const std::vector<std::pair<std::string, double>>& overrides)
{
	const SceneEntry* entry = findScene(name);
	if (!entry)
		throw std::invalid_argument("unknown scene '" + name + "'; valid scenes: " + sceneNames());
	try
	{
		return entry->create(world, withOverrides(entry->defaults, overrides));
	}
	catch (const std::invalid_argument& error)
	{
		throw std::invalid_argument("scene '" + name + "': " + error.what());
	}
}

void printRegistry(std::ostream& out)
{
	for (const SceneEntry& e : registry())
	{
		out << e.category << "/" << e.name << ": " << e.description << "\n";
		for (const Param& p : e.defaults)
			out << "    " << p.name << " = " << p.value << " " << p.unit << "  " << p.description << "\n";
	}
}

}  // namespace scenes
