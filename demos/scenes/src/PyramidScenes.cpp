// Many-body stacking: pyramid, overlap_recovery, sparse_stacking, dense_random.

#include "SceneBuild.h"
#include "SceneCatalog.h"

#include <cmath>
#include <cstdint>
#include <random>

namespace scenes
{
namespace
{
/// A 2-D pyramid in the x-y plane: row r (0 = bottom) has base - r boxes, each row shifted by half a
/// box. Neighbours in a row are `sideGap` apart; each row sinks `verticalOverlap` into the one below
/// (and the bottom row into the ground). Returns the bodies row by row, left to right.
std::vector<btRigidBody*> addPyramid(SceneContent& content, int base, const btVector3& half, btScalar verticalOverlap,
									 btScalar sideGap, btScalar mass, btScalar mu)
{
	btCollisionShape* shape = content.addShape(new btBoxShape(half));
	const btScalar pitch = 2 * half.x() + sideGap;  // m, centre distance of neighbours in a row
	std::vector<btRigidBody*> bodies;
	bodies.reserve(size_t(base) * size_t(base + 1) / 2);
	for (int row = 0; row < base; ++row)
	{
		const int count = base - row;
		const btScalar firstX = -btScalar(count - 1) * pitch / 2;  // every row is centred on x = 0
		const btScalar y = build::columnCentreY(0, half.y(), row, verticalOverlap);
		for (int i = 0; i < count; ++i)
			bodies.push_back(content.addBody(shape, mass, build::at(firstX + btScalar(i) * pitch, y, 0), mu));
	}
	content.name("bottomLeft", bodies.front());
	content.name("top", bodies.back());
	return bodies;
}

/// Uniform number in [0, 1) from the raw 32-bit output, so the sequence is the same with every standard
/// library (std::uniform_real_distribution is implementation-defined).
double unitRandom(std::mt19937& rng) { return double(rng()) / 4294967296.0; }

/// Uniformly distributed random rotation (Shoemake's method).
btQuaternion randomRotation(std::mt19937& rng)
{
	const double u1 = unitRandom(rng), u2 = unitRandom(rng), u3 = unitRandom(rng);
	const double twoPi = 2 * SIMD_PI;
	const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
	return btQuaternion(btScalar(a * std::sin(twoPi * u2)), btScalar(a * std::cos(twoPi * u2)),
						btScalar(b * std::sin(twoPi * u3)), btScalar(b * std::cos(twoPi * u3)));
}

}  // namespace

// ---------------------------------------------------------------------------------------------------
// pyramid: dense structured stacking, base * (base + 1) / 2 boxes; base = 140 gives 9,870 bodies.

Params pyramidParams()
{
	return {
		{"base", 20, "-", "boxes in the bottom row"},
		{"width", 1, "m", "box extent along x"},
		{"height", 0.5, "m", "box extent along y"},
		{"depth", 1, "m", "box extent along z"},
		{"gap", build::kSideGap, "m", "horizontal gap between neighbours in a row"},
		{"mass", 1, "kg", "mass of each box"},
		{"mu", 0.6, "-", build::kMuDescription},
	};
}

std::unique_ptr<SceneContent> createPyramid(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int base = build::countParam(params, "base", 1);
	const btVector3 half = btScalar(0.5) * btVector3(build::positiveParam(params, "width"), build::positiveParam(params, "height"), build::positiveParam(params, "depth"));
	const btScalar gap = build::nonNegativeParam(params, "gap");
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar mu = build::nonNegativeParam(params, "mu");

	auto content = std::make_unique<SceneContent>(world);
	const btScalar baseHalfWidth = btScalar(base) * (2 * half.x() + gap) / 2;  // m
	build::addGround(*content, 2 * baseHalfWidth, mu);
	addPyramid(*content, base, half, btScalar(build::kRestOverlap), gap, mass, mu);
	build::finishScene(*content, true);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// overlap_recovery: a small pyramid of cubes whose every row starts sunk into its support by a fraction
// of the cube edge; a solver must push them apart without flinging them.

Params overlapRecoveryParams()
{
	return {
		{"base", 4, "-", "cubes in the bottom row"},
		{"overlap", 0.25, "-", "initial penetration of each row into its support, as a fraction of the edge"},
		{"size", 0.5, "m", "cube edge"},
		{"mass", 1, "kg", "mass of each cube"},
		{"mu", 0.6, "-", build::kMuDescription},
	};
}

std::unique_ptr<SceneContent> createOverlapRecovery(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int base = build::countParam(params, "base", 1);
	const btScalar overlap = build::nonNegativeParam(params, "overlap");
	const btScalar size = build::positiveParam(params, "size");
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	build::require(overlap < btScalar(0.5), "overlap must be < 0.5 so the push-out direction is unambiguous");
	const btScalar half = size / 2;

	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, 2 * btScalar(base) * size, mu);
	addPyramid(*content, base, btVector3(half, half, half), overlap * size, btScalar(build::kSideGap), mass, mu);
	content->facts["size"] = size;
	content->facts["overlap"] = overlap;
	content->facts["overlapDepth"] = overlap * size;  // m
	build::finishScene(*content, false);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// sparse_stacking: several independent small stacks in a row along x.

Params sparseStackingParams()
{
	return {
		{"stacks", 4, "-", "number of stacks"},
		{"height", 3, "-", "cubes per stack"},
		{"size", 0.5, "m", "cube edge"},
		{"spacing", 2, "m", "distance between neighbouring stack centres"},
		{"mass", 1, "kg", "mass of each cube"},
		{"mu", 0.6, "-", build::kMuDescription},
	};
}

std::unique_ptr<SceneContent> createSparseStacking(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int stacks = build::countParam(params, "stacks", 1);
	const int height = build::countParam(params, "height", 1);
	const btScalar size = build::positiveParam(params, "size");
	const btScalar spacing = build::positiveParam(params, "spacing");
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	build::require(spacing >= size + btScalar(build::kSideGap), "spacing must exceed the cube edge");
	const btScalar half = size / 2;

	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, btScalar(stacks) * spacing + 2 * btScalar(height) * size, mu);
	btCollisionShape* shape = content->addShape(new btBoxShape(btVector3(half, half, half)));
	for (int s = 0; s < stacks; ++s)
	{
		const btScalar x = (btScalar(s) - btScalar(stacks - 1) / 2) * spacing;
		for (int level = 0; level < height; ++level)
		{
			btRigidBody* cube = content->addBody(shape, mass, build::at(x, build::columnCentreY(0, half, level), 0), mu);
			if (s == 0 && level == 0)
				content->name("bottom", cube);
			if (s == 0 && level == height - 1)
				content->name("top", cube);
		}
	}
	content->facts["stacks"] = stacks;
	build::finishScene(*content, true);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// dense_random: cubes dropped from a loose grid with seeded random offsets and rotations into a square
// pit of four static walls; they settle into a compact pile.

Params denseRandomParams()
{
	return {
		{"count", 100, "-", "number of cubes"},
		{"size", 0.5, "m", "cube edge"},
		{"seed", 1, "-", "seed of the std::mt19937 that draws offsets and rotations"},
		{"width", 4, "m", "inner side of the square pit between the walls"},
		{"dropHeight", 1, "m", "height of the lowest point of the grid above the ground"},
		{"mass", 1, "kg", "mass of each cube"},
		{"mu", 0.6, "-", build::kMuDescription},
	};
}

std::unique_ptr<SceneContent> createDenseRandom(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int count = build::countParam(params, "count", 1);
	const btScalar size = build::positiveParam(params, "size");
	const std::uint32_t seed = build::seedParam(params);
	const btScalar width = build::positiveParam(params, "width");
	const btScalar dropHeight = build::nonNegativeParam(params, "dropHeight");
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar mu = build::nonNegativeParam(params, "mu");

	// Each cube starts in its own grid cell, free to take any rotation: the cell must hold the cube's
	// circumscribed sphere (diameter size * sqrt(3)), plus 10% room for a random offset.
	const btScalar sphereDiameter = size * btSqrt(btScalar(3));
	const btScalar cellSlack = btScalar(0.1);                // -, extra cell size as a fraction of the sphere
	const btScalar cell = sphereDiameter * (1 + cellSlack);  // m
	const btScalar maxOffset = (cell - sphereDiameter) / 2;  // m, per axis; spheres of neighbours never meet
	const int perSide = int(std::floor((width - 2 * btScalar(build::kSideGap)) / cell));
	build::require(perSide >= 1, "width must hold at least one cube in any rotation (width > 1.1 sqrt(3) size)");
	const int perLayer = perSide * perSide;
	const int layers = (count + perLayer - 1) / perLayer;
	const btScalar gridTop = dropHeight + btScalar(layers) * cell;  // m

	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, 4 * width, mu);

	// Four static walls, as tall as the grid, whose inner faces bound the pit |x|, |z| <= width / 2.
	build::addSquarePit(*content, width, gridTop / 2, mu);

	std::mt19937 rng(seed);
	const btScalar half = size / 2;
	btCollisionShape* shape = content->addShape(new btBoxShape(btVector3(half, half, half)));
	const btScalar firstCell = -btScalar(perSide - 1) * cell / 2;  // m, centre of the first cell along x and z
	for (int i = 0; i < count; ++i)
	{
		const int layer = i / perLayer, column = (i % perLayer) % perSide, row = (i % perLayer) / perSide;
		const btVector3 cellCentre(firstCell + btScalar(column) * cell, dropHeight + (btScalar(layer) + btScalar(0.5)) * cell, firstCell + btScalar(row) * cell);
		btVector3 offset;
		for (int axis = 0; axis < 3; ++axis)
			offset[axis] = btScalar(2 * unitRandom(rng) - 1) * maxOffset;
		const btTransform xf(randomRotation(rng), cellCentre + offset);
		content->addBody(shape, mass, xf, mu);
	}
	content->facts["width"] = width;
	content->facts["wallHeight"] = gridTop;
	build::finishScene(*content, false);
	return content;
}

}  // namespace scenes
