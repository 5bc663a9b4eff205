// Scenes of the shape grid (issue 37): the same structures built from every body shape and on every
// ground Bullet apps use (src/ShapeKinds.cpp lists them): shape_column, round_on_block. The truth
// scenes harmonic_stack and pushed_stack take the same "shape" and "ground" parameters.

#include "SceneBuild.h"
#include "SceneCatalog.h"

namespace scenes
{
// ---------------------------------------------------------------------------------------------------
// shape_column: n equal bodies of one shape stacked upright on the ground, each centred on the one
// below: in equilibrium, so it stands (every shape with a flat top and bottom: kinds 0-5).

Params shapeColumnParams()
{
	return {
		{"n", 10, "-", "number of bodies"},
		{"shape", 0, "-", "body shape (0 box, 1 hull, 2 hull+features, 3 hexagonal prism, 4 cylinder, 5 compound)"},
		{"ground", 0, "-", "ground (0 box, 1 plane, 2 triangle mesh, 3 mesh+internal edges, 4 heightfield)"},
		{"width", 1, "m", "body extent along x and z (a cylinder's or prism's diameter)"},
		{"height", 0.5, "m", "body extent along y"},
		{"mass", 1, "kg", "mass of each body"},
		{"mu", 0.6, "-", build::kMuDescription},
	};
}

std::unique_ptr<SceneContent> createShapeColumn(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int n = build::countParam(params, "n", 1);
	const int shapeKind = build::countParam(params, "shape", 0);
	const btScalar width = build::positiveParam(params, "width");
	const btVector3 half(width / 2, build::positiveParam(params, "height") / 2, width / 2);
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	build::require(shapeKind <= build::kCompound, "shape must be 0-5: a column needs a flat top and bottom");

	auto content = std::make_unique<SceneContent>(world);
	build::addGroundOf(*content, build::countParam(params, "ground", 0), width, mu);
	btCollisionShape* shape = build::addShapeOf(*content, shapeKind, half);
	btRigidBody* body = nullptr;
	for (int level = 0; level < n; ++level)
	{
		body = content->addBody(shape, mass, build::at(0, build::columnCentreY(0, half.y(), level), 0), mu);
		if (level == 0)
			content->name("bottom", body);
	}
	content->name("top", body);
	build::finishScene(*content, true);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// round_on_block: a heavy round body (a sphere, or a capsule lying along x) resting on the middle of
// a light box's top face, the box on the ground: in equilibrium (the contact is under the round
// body's centre), so both stay at rest; the box carries `ratio` times its own weight.

Params roundOnBlockParams()
{
	return {
		{"shape", 7, "-", "round body (6 capsule lying along x, 7 sphere)"},
		{"ground", 0, "-", "ground (0 box, 1 plane, 2 triangle mesh, 3 mesh+internal edges, 4 heightfield)"},
		{"radius", 0.25, "m", "radius of the round body"},
		{"ratio", 100, "-", "mass of the round body over the box's (1 kg)"},
		{"mu", 0.6, "-", build::kMuDescription},
	};
}

std::unique_ptr<SceneContent> createRoundOnBlock(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int shapeKind = build::countParam(params, "shape", 0);
	const btScalar radius = build::positiveParam(params, "radius");
	const btScalar ratio = build::positiveParam(params, "ratio");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	build::require(shapeKind == build::kCapsule || shapeKind == build::kSphere, "shape must be 6 (capsule) or 7 (sphere)");
	const btVector3 boxHalf = build::standardBoxHalfExtents();

	auto content = std::make_unique<SceneContent>(world);
	build::addGroundOf(*content, build::countParam(params, "ground", 0), 2 * boxHalf.x(), mu);
	btRigidBody* box = content->addBody(content->addShape(new btBoxShape(boxHalf)), 1, build::at(0, build::columnCentreY(0, boxHalf.y(), 0), 0), mu);
	// The round body's extent along x: 2 radius for the sphere, 4 radius for the capsule.
	const btVector3 roundHalf(2 * radius, radius, radius);
	const btScalar y = 2 * boxHalf.y() - 2 * btScalar(build::kRestOverlap) + radius;
	btRigidBody* round = content->addBody(build::addShapeOf(*content, shapeKind, roundHalf), ratio, build::at(0, y, 0), mu);
	content->name("bottom", box);
	content->name("top", round);
	build::finishScene(*content, true);
	return content;
}

}  // namespace scenes

namespace scenes
{
// ---------------------------------------------------------------------------------------------------
// leaning_plank: a plank (a box, length L, thickness t) leaning at `angle` from the floor against a
// static wall, its lower edge on the ground and its upper edge on the wall's face, friction mu at
// both. Statics at impending slip (floor friction towards the wall, wall friction up, both mu times
// their normal force) gives with the plank's weight W at its centre, its half length h, half
// thickness e, c = cos(angle), s = sin(angle) and the contact points' offsets from the centre
//   floor  r_f = (h c - e s, -h s - e c),   wall  r_w = (-h c - e s, h s - e c)
// the moment about the centre per unit floor normal force
//   g(mu) = r_f.x + mu r_f.y + mu^2 r_w.x - mu r_w.y,
// which is positive (gravity's turn exceeds what friction can hold) below the critical mu and
// negative above it: the plank stands iff g(mu) <= 0. For a thin plank this is Coulomb's ladder,
// tan(angle) >= (1 - mu^2) / (2 mu). The critical mu (the root of g) is the fact "criticalMu".

Params leaningPlankParams()
{
	return {
		{"angle", 60, "deg", "angle between the plank and the floor"},
		{"mu", 0.45, "-", build::kMuDescription},
		{"length", 2, "m", "plank length"},
		{"thickness", 0.1, "m", "plank thickness"},
		{"mass", 10, "kg", "plank mass"},
		{"ground", 0, "-", "ground (0 box, 1 plane, 2 triangle mesh, 3 mesh+internal edges, 4 heightfield)"},
	};
}

std::unique_ptr<SceneContent> createLeaningPlank(btDiscreteDynamicsWorld& world, const Params& params)
{
	const btScalar angle = build::degreesToRadians(build::positiveParam(params, "angle"));
	const btScalar mu = build::nonNegativeParam(params, "mu");
	const btScalar h = build::positiveParam(params, "length") / 2;
	const btScalar e = build::positiveParam(params, "thickness") / 2;
	const btScalar mass = build::positiveParam(params, "mass");
	build::require(angle < SIMD_HALF_PI, "angle must be below 90 degrees");
	const btScalar c = btCos(angle), s = btSin(angle);
	const btScalar overlap = btScalar(build::kRestOverlap);

	auto content = std::make_unique<SceneContent>(world);
	build::addGroundOf(*content, build::countParam(params, "ground", 0), 4 * h, mu);
	// The wall: a static box whose face towards the plank is the plane x = 0.
	btRigidBody* wall = content->addBody(content->addShape(new btBoxShape(btVector3(btScalar(0.5), 2 * h + 1, 2))), 0,
										 build::at(btScalar(-0.5), 2 * h + 1, 0), mu);
	content->name("wall", wall);
	// The plank's long axis points from its foot up to the wall: (-c, s, 0); its thickness axis
	// (-s, -c, 0). Its lowest corner touches the floor and its leftmost the wall.
	const btVector3 centre(h * c + e * s - overlap, h * s + e * c - overlap, 0);
	btRigidBody* plank = content->addBody(content->addShape(new btBoxShape(btVector3(h, e, btScalar(0.25)))), mass,
										  build::rotatedAt(btVector3(0, 0, 1), SIMD_PI - angle, centre), mu);
	content->name("top", plank);
	content->name("bottom", plank);
	content->name("plank", plank);
	// The critical mu: the root of g on [0, 10] by bisection (g falls with mu on it).
	const double rfx = h * c - e * s, rfy = -h * s - e * c, rwx = -h * c - e * s, rwy = h * s - e * c;
	auto g = [&](double m) { return rfx + m * rfy + m * m * rwx - m * rwy; };
	double low = 0, high = 10;
	for (int i = 0; i < 100; ++i) (g((low + high) / 2) > 0 ? low : high) = (low + high) / 2;
	content->facts["criticalMu"] = (low + high) / 2;
	build::finishScene(*content, g(mu) <= 0);
	return content;
}

}  // namespace scenes
