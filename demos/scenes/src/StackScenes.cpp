// Single boxes and vertical stacks: single_box, sliding_box, free_fall, tower, mass_ratio_tower,
// large_on_small, leaning_tower.

#include "SceneBuild.h"
#include "SceneCatalog.h"

namespace scenes
{
namespace
{
/// One standard 1 x 0.5 x 1 m box named "box" whose centre is at `centre`, on a default ground.
std::unique_ptr<SceneContent> oneBoxScene(btDiscreteDynamicsWorld& world, btScalar mass, btScalar mu, const btVector3& centre)
{
	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, 0, mu);
	btCollisionShape* shape = content->addShape(new btBoxShape(build::standardBoxHalfExtents()));
	content->name("box", content->addBody(shape, mass, build::at(centre.x(), centre.y(), centre.z()), mu));
	return content;
}

/// Centre height of a standard box resting on the ground.
btScalar restingStandardBoxY() { return build::columnCentreY(0, build::standardBoxHalfExtents().y(), 0); }

}  // namespace

// ---------------------------------------------------------------------------------------------------
// single_box: the smallest resting contact.

Params singleBoxParams()
{
	return {
		{"mu", 0.6, "-", build::kMuDescription},
		{"mass", 1, "kg", "mass of the box"},
	};
}

std::unique_ptr<SceneContent> createSingleBox(btDiscreteDynamicsWorld& world, const Params& params)
{
	const btScalar mu = build::nonNegativeParam(params, "mu");
	const btScalar mass = build::positiveParam(params, "mass");
	auto content = oneBoxScene(world, mass, mu, btVector3(0, restingStandardBoxY(), 0));
	build::finishScene(*content, true);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// sliding_box: a box launched along +x on the ground; Coulomb friction stops it after
// v0^2 / (2 mu g) metres.

Params slidingBoxParams()
{
	return {
		{"mu", 0.5, "-", build::kMuDescription},
		{"v0", 5, "m/s", "initial speed along +x"},
		{"mass", 1, "kg", "mass of the box"},
	};
}

std::unique_ptr<SceneContent> createSlidingBox(btDiscreteDynamicsWorld& world, const Params& params)
{
	const btScalar mu = build::nonNegativeParam(params, "mu");
	const btScalar v0 = btScalar(getParam(params, "v0"));
	const btScalar mass = build::positiveParam(params, "mass");
	auto content = oneBoxScene(world, mass, mu, btVector3(0, restingStandardBoxY(), 0));
	content->named("box")->setLinearVelocity(btVector3(v0, 0, 0));
	content->facts["mu"] = mu;
	content->facts["v0"] = v0;
	build::finishScene(*content, false);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// free_fall: no contacts at all; the box follows y = h0 - g t^2 / 2 until it lands.

Params freeFallParams()
{
	return {
		{"h0", 10, "m", "initial height of the box centre"},
		{"mass", 1, "kg", "mass of the box"},
	};
}

std::unique_ptr<SceneContent> createFreeFall(btDiscreteDynamicsWorld& world, const Params& params)
{
	const btScalar h0 = build::positiveParam(params, "h0");
	const btScalar mass = build::positiveParam(params, "mass");
	build::require(h0 > build::standardBoxHalfExtents().y(), "h0 must put the box above the ground");
	const btScalar groundMu = 1;  // irrelevant until it lands
	auto content = oneBoxScene(world, mass, groundMu, btVector3(0, h0, 0));
	content->facts["h0"] = h0;
	build::finishScene(*content, false);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// tower: n boxes on top of each other, optionally offset alternately along x (as in Solver2D).

Params towerParams()
{
	return {
		{"n", 20, "-", "number of boxes"},
		{"width", 1, "m", "box extent along x"},
		{"height", 0.5, "m", "box extent along y"},
		{"depth", 1, "m", "box extent along z"},
		{"mass", 1, "kg", "mass of each box"},
		{"mu", 0.6, "-", build::kMuDescription},
		{"offset", 0, "m", "x offset of each level, alternating + and - (0: perfectly aligned)"},
	};
}

std::unique_ptr<SceneContent> createTower(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int n = build::countParam(params, "n", 1);
	const btVector3 half = btScalar(0.5) * btVector3(build::positiveParam(params, "width"), build::positiveParam(params, "height"), build::positiveParam(params, "depth"));
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	const btScalar offset = build::nonNegativeParam(params, "offset");
	build::require(offset < half.x(), "offset must be below half the width so neighbouring levels overlap");

	auto content = std::make_unique<SceneContent>(world);
	const btScalar towerHeight = 2 * half.y() * btScalar(n);  // m; a toppled tower lies within this radius
	build::addGround(*content, 2 * towerHeight, mu);
	btCollisionShape* shape = content->addShape(new btBoxShape(half));
	btRigidBody* box = nullptr;
	for (int level = 0; level < n; ++level)
	{
		const btScalar x = (level % 2 == 0) ? offset : -offset;
		box = content->addBody(shape, mass, build::at(x, build::columnCentreY(0, half.y(), level), 0), mu);
		if (level == 0)
			content->name("bottom", box);
	}
	content->name("top", box);
	build::finishScene(*content, true);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// mass_ratio_tower: standard boxes with a top box `ratio` times heavier; every Bullet solver crushes it.

Params massRatioTowerParams()
{
	return {
		{"n", 4, "-", "number of boxes, the heavy one included"},
		{"ratio", 1000, "-", "mass of the top box / mass of each other box"},
		{"mass", 1, "kg", "mass of each light box"},
		{"mu", 0.6, "-", build::kMuDescription},
	};
}

std::unique_ptr<SceneContent> createMassRatioTower(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int n = build::countParam(params, "n", 2);
	const btScalar ratio = build::positiveParam(params, "ratio");
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	const btVector3 half = build::standardBoxHalfExtents();

	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, 2 * half.y() * btScalar(2 * n), mu);
	btCollisionShape* shape = content->addShape(new btBoxShape(half));
	for (int level = 0; level < n; ++level)
	{
		const bool isTop = (level == n - 1);
		btRigidBody* box = content->addBody(shape, isTop ? ratio * mass : mass, build::at(0, build::columnCentreY(0, half.y(), level), 0), mu);
		if (level == 0)
			content->name("bottom", box);
		if (isTop)
			content->name("top", box);
	}
	content->facts["ratio"] = ratio;
	build::finishScene(*content, true);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// large_on_small: a heavy slab bridging two small light cubes placed under its ends.

Params largeOnSmallParams()
{
	return {
		{"ratio", 100, "-", "mass of the large box / mass of one small box"},
		{"smallMass", 1, "kg", "mass of each small box"},
		{"smallSize", 0.5, "m", "edge of each small cube"},
		{"largeWidth", 4, "m", "extent of the large box along x"},
		{"largeHeight", 0.5, "m", "extent of the large box along y"},
		{"largeDepth", 1, "m", "extent of the large box along z"},
		{"mu", 0.6, "-", build::kMuDescription},
	};
}

std::unique_ptr<SceneContent> createLargeOnSmall(btDiscreteDynamicsWorld& world, const Params& params)
{
	const btScalar ratio = build::positiveParam(params, "ratio");
	const btScalar smallMass = build::positiveParam(params, "smallMass");
	const btScalar smallHalf = btScalar(0.5) * build::positiveParam(params, "smallSize");
	const btVector3 largeHalf = btScalar(0.5) * btVector3(build::positiveParam(params, "largeWidth"), build::positiveParam(params, "largeHeight"), build::positiveParam(params, "largeDepth"));
	const btScalar mu = build::nonNegativeParam(params, "mu");
	// Each support sits under an end of the slab, inset by half its own edge.
	const btScalar supportX = largeHalf.x() - 2 * smallHalf;
	build::require(supportX > smallHalf, "largeWidth must be wider than four small boxes");

	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, 4 * largeHalf.x(), mu);
	btCollisionShape* smallShape = content->addShape(new btBoxShape(btVector3(smallHalf, smallHalf, smallHalf)));
	const btScalar supportY = build::columnCentreY(0, smallHalf, 0);
	content->name("leftSupport", content->addBody(smallShape, smallMass, build::at(-supportX, supportY, 0), mu));
	content->name("rightSupport", content->addBody(smallShape, smallMass, build::at(supportX, supportY, 0), mu));
	const btScalar supportTopY = supportY + smallHalf;
	btCollisionShape* largeShape = content->addShape(new btBoxShape(largeHalf));
	btRigidBody* large = content->addBody(largeShape, ratio * smallMass, build::at(0, build::columnCentreY(supportTopY, largeHalf.y(), 0), 0), mu);
	content->name("large", large);
	content->facts["ratio"] = ratio;
	build::finishScene(*content, true);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// leaning_tower: cubes each shifted along +x by a fraction of their width; it topples as soon as the
// centre of mass of the boxes above some box lies beyond that box's edge.

Params leaningTowerParams()
{
	return {
		{"n", 6, "-", "number of cubes"},
		{"shift", 0.3, "-", "x shift of each cube relative to the one below, as a fraction of the edge"},
		{"size", 0.5, "m", "cube edge"},
		{"mass", 1, "kg", "mass of each cube"},
		{"mu", 0.6, "-", build::kMuDescription},
	};
}

std::unique_ptr<SceneContent> createLeaningTower(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int n = build::countParam(params, "n", 2);
	const btScalar shift = build::nonNegativeParam(params, "shift");
	const btScalar size = build::positiveParam(params, "size");
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	build::require(shift < 1, "shift must be < 1 so each cube rests on the one below");
	const btScalar half = size / 2;
	const btScalar step = shift * size;  // m, x shift per level

	// Statics: the cubes above level k have their centre of mass at the mean of their x positions; the
	// tower falls if that lies beyond the right edge of cube k for any k.
	bool falls = false;
	for (int k = 0; k + 1 < n; ++k)
	{
		const btScalar meanXAbove = step * btScalar(k + 1 + n - 1) / 2;  // m, mean of step * (k+1 .. n-1)
		if (meanXAbove - step * btScalar(k) > half)
			falls = true;
	}
	const btScalar comAboveBottom = step * btScalar(n) / 2;  // m, x of the centre of mass of cubes 1..n-1

	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, 4 * size * btScalar(n), mu);
	btCollisionShape* shape = content->addShape(new btBoxShape(btVector3(half, half, half)));
	btRigidBody* cube = nullptr;
	for (int level = 0; level < n; ++level)
	{
		cube = content->addBody(shape, mass, build::at(step * btScalar(level), build::columnCentreY(0, half, level), 0), mu);
		if (level == 0)
			content->name("bottom", cube);
	}
	content->name("top", cube);
	content->facts["expectFalls"] = falls ? 1 : 0;
	content->facts["comOffset"] = comAboveBottom;  // m, relative to the bottom cube's centre
	content->facts["halfWidth"] = half;
	build::finishScene(*content, !falls);
	return content;
}

}  // namespace scenes
