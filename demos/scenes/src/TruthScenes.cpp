// Scenes of the truth suite (demos/truth): small structures whose outcome statics or Coulomb friction
// predicts in closed form: harmonic_stack, pushed_stack, ramp_stack, loaded_lintel.

#include "SceneBuild.h"
#include "SceneCatalog.h"

#include <cmath>
#include <string>

namespace scenes
{
namespace
{
/// Boxes added with addBody(..., boxMu) have friction sqrt(boxMu), so two boxes combine to boxMu (Bullet
/// multiplies a pair's coefficients). This is the friction a static body needs to combine with such a
/// box to `pairMu`.
btScalar staticFrictionFor(btScalar pairMu, btScalar boxMu) { return pairMu / btSqrt(boxMu); }
}  // namespace

// ---------------------------------------------------------------------------------------------------
// harmonic_stack: n cubes of edge a, the cube k-th from the top shifted scale * a / (2k) along +x past the
// one below (the book-stacking overhang). The top k cubes have their centre of mass scale * a / 2 past the
// centre of cube k + 1 (sum over j of the shifts below cube j, divided by k, is k * scale * a / 2 / k), so
// at scale 1 every sub-stack's centre of mass is exactly over its support's edge: it stands iff scale <= 1.

Params harmonicStackParams()
{
	return {
		{"n", 6, "-", "number of cubes"},
		{"scale", 0.85, "-", "overhang as a fraction of the harmonic one (stands iff <= 1)"},
		{"size", 0.5, "m", "cube edge"},
		{"mass", 1, "kg", "mass of each cube"},
		{"mu", 0.6, "-", build::kMuDescription},
		{"shape", 0, "-", "body shape (0 box, 1 hull, 2 hull+features, 3 hexagonal prism, 4 cylinder, 5 compound)"},
		{"ground", 0, "-", "ground (0 box, 1 plane, 2 triangle mesh, 3 mesh+internal edges, 4 heightfield)"},
	};
}

std::unique_ptr<SceneContent> createHarmonicStack(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int n = build::countParam(params, "n", 2);
	const btScalar scale = build::nonNegativeParam(params, "scale");
	const btScalar size = build::positiveParam(params, "size");
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	build::require(scale < 2, "scale must be < 2 so each cube rests on the one below");
	const btScalar half = size / 2;

	const int shapeKind = build::countParam(params, "shape", 0);
	build::require(shapeKind <= build::kCompound, "shape must be 0-5: a stack needs a flat top and bottom");

	auto content = std::make_unique<SceneContent>(world);
	build::addGroundOf(*content, build::countParam(params, "ground", 0), 4 * size * btScalar(n), mu);
	btCollisionShape* shape = build::addShapeOf(*content, shapeKind, btVector3(half, half, half));
	btScalar x = 0;
	btRigidBody* cube = nullptr;
	for (int level = 0; level < n; ++level)
	{
		if (level > 0)
		{
			const int fromTop = n - level;  // 1 for the top cube
			x += scale * size / (2 * btScalar(fromTop));
		}
		cube = content->addBody(shape, mass, build::at(x, build::columnCentreY(0, half, level), 0), mu);
		if (level == 0)
			content->name("bottom", cube);
	}
	content->name("top", cube);
	content->facts["comOverhang"] = scale * half;  // m, each sub-stack's COM past its support's centre
	content->facts["halfWidth"] = half;
	build::finishScene(*content, scale <= 1);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// pushed_stack: n equal boxes stacked on the ground, box-ground friction groundMu and box-box friction
// boxMu (combined values; the ground gets groundMu / sqrt(boxMu), each box sqrt(boxMu)). A horizontal force
// F on the bottom box (applied by the caller) moves the stack iff F > groundMu * total weight; then it
// slides as one body at (F - groundMu W) / M as long as boxMu exceeds what holding the boxes above needs.

Params pushedStackParams()
{
	return {
		{"n", 5, "-", "number of boxes"},
		{"width", 1, "m", "box extent along x"},
		{"height", 0.5, "m", "box extent along y"},
		{"depth", 1, "m", "box extent along z"},
		{"mass", 1, "kg", "mass of each box"},
		{"groundMu", 0.5, "-", "combined friction of the bottom box on the ground"},
		{"boxMu", 1, "-", "combined friction between two boxes"},
		{"shape", 0, "-", "body shape (0 box, 1 hull, 2 hull+features, 3 hexagonal prism, 4 cylinder, 5 compound)"},
		{"ground", 0, "-", "ground (0 box, 1 plane, 2 triangle mesh, 3 mesh+internal edges, 4 heightfield)"},
	};
}

std::unique_ptr<SceneContent> createPushedStack(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int n = build::countParam(params, "n", 1);
	const btVector3 half = btScalar(0.5) * btVector3(build::positiveParam(params, "width"), build::positiveParam(params, "height"), build::positiveParam(params, "depth"));
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar groundMu = build::nonNegativeParam(params, "groundMu");
	const btScalar boxMu = build::positiveParam(params, "boxMu");

	const int shapeKind = build::countParam(params, "shape", 0);
	build::require(shapeKind <= build::kCompound, "shape must be 0-5: a stack needs a flat top and bottom");

	auto content = std::make_unique<SceneContent>(world);
	btRigidBody* ground = build::addGroundOf(*content, build::countParam(params, "ground", 0), 0, groundMu);
	ground->setFriction(staticFrictionFor(groundMu, boxMu));
	btCollisionShape* shape = build::addShapeOf(*content, shapeKind, half);
	btRigidBody* box = nullptr;
	for (int level = 0; level < n; ++level)
	{
		box = content->addBody(shape, mass, build::at(0, build::columnCentreY(0, half.y(), level), 0), boxMu);
		content->name("box" + std::to_string(level), box);
		if (level == 0)
			content->name("bottom", box);
	}
	content->name("top", box);
	content->facts["groundMu"] = groundMu;
	content->facts["boxMu"] = boxMu;
	build::finishScene(*content, true);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// ramp_stack: n equal boxes stacked on a static ramp of angle alpha descending towards +x, box-ramp friction
// rampMu and box-box friction boxMu (combined). The stack sticks iff rampMu >= tan(alpha); otherwise it
// slides as one body at g (sin alpha - rampMu cos alpha), provided boxMu holds the boxes above together.

Params rampStackParams()
{
	return {
		{"angleDeg", 20, "deg", "ramp inclination"},
		{"n", 3, "-", "number of boxes"},
		{"width", 1, "m", "box extent along the slope"},
		{"height", 0.5, "m", "box extent normal to the slope"},
		{"depth", 1, "m", "box extent across the slope"},
		{"mass", 1, "kg", "mass of each box"},
		{"rampMu", 0.5, "-", "combined friction of the bottom box on the ramp"},
		{"boxMu", 1, "-", "combined friction between two boxes"},
		{"rampLength", 10, "m", "ramp extent along its slope; the stack starts one box width below its top"},
	};
}

std::unique_ptr<SceneContent> createRampStack(btDiscreteDynamicsWorld& world, const Params& params)
{
	const btScalar angle = build::degreesToRadians(build::positiveParam(params, "angleDeg"));
	const int n = build::countParam(params, "n", 1);
	const btVector3 half = btScalar(0.5) * btVector3(build::positiveParam(params, "width"), build::positiveParam(params, "height"), build::positiveParam(params, "depth"));
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar rampMu = build::nonNegativeParam(params, "rampMu");
	const btScalar boxMu = build::positiveParam(params, "boxMu");
	const btScalar rampHalfLength = build::positiveParam(params, "rampLength") / 2;
	build::require(angle < SIMD_HALF_PI, "angleDeg must be below 90");
	build::require(rampHalfLength > 2 * half.x(), "rampLength must be at least two box widths");
	const btScalar rampHalfThickness = btScalar(0.1);  // m

	auto content = std::make_unique<SceneContent>(world);
	btRigidBody* ground = build::addGround(*content, 2 * rampHalfLength, rampMu);
	ground->setFriction(staticFrictionFor(rampMu, boxMu));

	// The slope descends towards +x; its top face meets the ground's top at its lower end.
	const btScalar rampCentreY = rampHalfLength * btSin(angle) - rampHalfThickness * btCos(angle);
	const btTransform rampXf = build::rotatedAt(btVector3(0, 0, 1), -angle, btVector3(0, rampCentreY, 0));
	btCollisionShape* rampShape = content->addShape(new btBoxShape(btVector3(rampHalfLength, rampHalfThickness, 2 * half.z())));
	btRigidBody* ramp = content->addBody(rampShape, 0, rampXf, rampMu);
	ramp->setFriction(staticFrictionFor(rampMu, boxMu));
	content->name("ramp", ramp);

	btCollisionShape* shape = content->addShape(new btBoxShape(half));
	const btScalar alongSlope = -rampHalfLength + 2 * half.x();  // m from the ramp centre, near its top
	btRigidBody* box = nullptr;
	for (int level = 0; level < n; ++level)
	{
		// Height above the ramp's mid-plane, each box sinking the rest overlap into what it rests on.
		const btScalar normal = build::columnCentreY(rampHalfThickness, half.y(), level);
		const btTransform xf(rampXf.getRotation(), rampXf * btVector3(alongSlope, normal, 0));
		box = content->addBody(shape, mass, xf, boxMu);
		content->name("box" + std::to_string(level), box);
		if (level == 0)
			content->name("bottom", box);
	}
	content->name("top", box);
	content->facts["angleRad"] = angle;
	content->facts["tanAngle"] = btTan(angle);
	content->facts["rampMu"] = rampMu;
	content->facts["boxMu"] = boxMu;
	build::finishScene(*content, rampMu >= btTan(angle));
	return content;
}

// ---------------------------------------------------------------------------------------------------
// ledge_column: n aligned cubes of edge a on a static ledge whose edge (x = 0) runs under the column,
// the column's axis `overhang` a past it. Every sub-stack sits squarely on the cube below, so only
// the whole column can move: for overhang > 0 its weight acts outside its support and it tips about
// the ledge's edge as one rigid body. Rigid-body dynamics from rest: angular acceleration
// alpha = M g e / I_edge, e = overhang a (the centre's lever arm), I_edge = M (a^2 + (n a)^2) / 12
// + M (e^2 + (n a / 2)^2) (parallel axes about the edge), so alpha = g e / ((a^2 + n^2 a^2) / 12 +
// e^2 + n^2 a^2 / 4).

Params ledgeColumnParams()
{
	return {
		{"n", 6, "-", "number of cubes"},
		{"size", 0.5, "m", "cube edge"},
		{"overhang", 0.2, "-", "x of the column's axis past the ledge's edge, as a fraction of the edge (tips iff > 0; must be < 0.5)"},
		{"mass", 1, "kg", "mass of each cube"},
		{"mu", 0.8, "-", build::kMuDescription},
		{"ledgeHeight", 2, "m", "height of the ledge's top above the ground"},
	};
}

std::unique_ptr<SceneContent> createLedgeColumn(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int n = build::countParam(params, "n", 1);
	const btScalar size = build::positiveParam(params, "size");
	const btScalar overhang = build::nonNegativeParam(params, "overhang");
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	const btScalar ledgeHeight = build::positiveParam(params, "ledgeHeight");
	build::require(overhang < btScalar(0.5), "overhang must be < 0.5 so the column rests on the ledge");
	const btScalar half = size / 2;
	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, 4 * size * btScalar(n), mu);
	// The ledge: a static box from x = -2 n a to its edge at x = 0, standing on the ground.
	const btScalar ledgeHalfX = size * btScalar(n);
	btCollisionShape* ledgeShape = content->addShape(new btBoxShape(btVector3(ledgeHalfX, ledgeHeight / 2, 2 * size)));
	btRigidBody* ledge = content->addBody(ledgeShape, 0, build::at(-ledgeHalfX, ledgeHeight / 2, 0), mu);
	content->name("ledge", ledge);
	btCollisionShape* shape = content->addShape(new btBoxShape(btVector3(half, half, half)));
	const btScalar x = overhang * size;
	btRigidBody* cube = nullptr;
	for (int level = 0; level < n; ++level)
	{
		cube = content->addBody(shape, mass, build::at(x, build::columnCentreY(ledgeHeight, half, level), 0), mu);
		if (level == 0)
			content->name("bottom", cube);
	}
	content->name("top", cube);
	const double a = size, e = x, h = a * n;
	content->facts["tipAcceleration"] = 9.81 * e / ((a * a + h * h) / 12 + e * e + h * h / 4);  // rad/s^2 at g = 9.81
	content->facts["expectFalls"] = overhang > 0 ? 1 : 0;
	build::finishScene(*content, !(overhang > 0));
	return content;
}

// ---------------------------------------------------------------------------------------------------
// loaded_lintel: a lintel on two columns of cubes with a heavy box off centre. Each column ends in a thin
// cap (capWidth along x), so where on its top the lintel pushes moves the lever arms by at most
// capWidth / span: on the columns' full 0.5 m faces the split would be statically indeterminate (any
// force distribution over the two faces balancing the moment is an equilibrium). Lever rule at the cap
// centres x = -+span/2: the right cap carries W_lintel / 2 + W_load (1/2 + offset / span).

Params loadedLintelParams()
{
	return {
		{"count", 2, "-", "cubes in each column"},
		{"size", 0.5, "m", "edge of the column cubes and of the load box; depth of caps and lintel"},
		{"mass", 1, "kg", "mass of each column cube"},
		{"span", 2.5, "m", "distance between the column centres"},
		{"capWidth", 0.1, "m", "cap extent along x"},
		{"capHeight", 0.1, "m", "cap extent along y"},
		{"capMass", 0.2, "kg", "mass of each cap"},
		{"lintelLength", 3, "m", "lintel extent along x"},
		{"lintelHeight", 0.25, "m", "lintel extent along y"},
		{"lintelMass", 2, "kg", "mass of the lintel"},
		{"loadMass", 5, "kg", "mass of the load box"},
		{"offset", 0.6, "m", "load centre's distance from the lintel centre towards the right column"},
		{"mu", 0.6, "-", build::kMuDescription},
	};
}

std::unique_ptr<SceneContent> createLoadedLintel(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int count = build::countParam(params, "count", 1);
	const btScalar size = build::positiveParam(params, "size");
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar span = build::positiveParam(params, "span");
	const btScalar capWidth = build::positiveParam(params, "capWidth");
	const btScalar capHeight = build::positiveParam(params, "capHeight");
	const btScalar capMass = build::positiveParam(params, "capMass");
	const btVector3 lintelHalf = btScalar(0.5) * btVector3(build::positiveParam(params, "lintelLength"), build::positiveParam(params, "lintelHeight"), size);
	const btScalar lintelMass = build::positiveParam(params, "lintelMass");
	const btScalar loadMass = build::positiveParam(params, "loadMass");
	const btScalar offset = build::nonNegativeParam(params, "offset");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	build::require(span > size + btScalar(build::kSideGap), "span must keep the columns apart");
	build::require(capWidth <= size, "capWidth must not exceed the column width");
	build::require(lintelHalf.x() >= (span + capWidth) / 2, "lintelLength must cover both caps");
	build::require(offset + size / 2 <= lintelHalf.x(), "offset must keep the load on the lintel");

	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, 2 * lintelHalf.x(), mu);
	btCollisionShape* cubeShape = content->addShape(new btBoxShape(btVector3(size / 2, size / 2, size / 2)));
	btCollisionShape* capShape = content->addShape(new btBoxShape(btVector3(capWidth / 2, capHeight / 2, size / 2)));
	const char* sides[2] = {"left", "right"};
	btScalar capTop = 0;
	for (int side = 0; side < 2; ++side)
	{
		const btScalar x = (side == 0 ? -span : span) / 2;
		for (int level = 0; level < count; ++level)
			content->addBody(cubeShape, mass, build::at(x, build::columnCentreY(0, size / 2, level), 0), mu);
		const btScalar columnTop = build::columnCentreY(0, size / 2, count - 1) + size / 2;
		const btScalar capY = build::columnCentreY(columnTop, capHeight / 2, 0);
		content->name(std::string(sides[side]) + "Cap", content->addBody(capShape, capMass, build::at(x, capY, 0), mu));
		capTop = capY + capHeight / 2;
	}
	btCollisionShape* lintelShape = content->addShape(new btBoxShape(lintelHalf));
	const btScalar lintelY = build::columnCentreY(capTop, lintelHalf.y(), 0);
	content->name("lintel", content->addBody(lintelShape, lintelMass, build::at(0, lintelY, 0), mu));
	const btScalar loadY = build::columnCentreY(lintelY + lintelHalf.y(), size / 2, 0);
	content->name("load", content->addBody(cubeShape, loadMass, build::at(offset, loadY, 0), mu));
	content->facts["rightShare"] = 0.5 + offset / span;  // share of the load on the right cap
	build::finishScene(*content, true);
	return content;
}

}  // namespace scenes
