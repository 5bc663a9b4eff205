// Scenes meant to move, with an outcome physics predicts: seesaw, friction_ramp, domino_row,
// hinge_bridge.

#include "SceneBuild.h"
#include "SceneCatalog.h"

#include <cmath>

namespace scenes
{
namespace
{
/// Half angle (rad) of the circular arc on which `n` equal chords span `ratio` times their total
/// length: ratio = sin(phi) / (n sin(phi / n)), which falls from 1 at phi = 0 to 0 at phi = pi (n >= 2).
double arcHalfAngle(int n, double ratio)
{
	if (ratio >= 1)
		return 0;
	double low = 0, high = SIMD_PI;
	for (int i = 0; i < 100; ++i)  // bisection; 100 halvings reach double precision
	{
		const double mid = (low + high) / 2;
		if (std::sin(mid) / (n * std::sin(mid / n)) > ratio)
			low = mid;
		else
			high = mid;
	}
	return (low + high) / 2;
}

}  // namespace

// ---------------------------------------------------------------------------------------------------
// seesaw: a level plank balanced on a static edge, a stack of cubes on its left end and one cube on its
// right end; the left (-x) side must go down and the plank must carry the full weight.

Params seesawParams()
{
	return {
		{"stack", 5, "-", "cubes stacked on the left end"},
		{"plankLength", 6, "m", "plank extent along x"},
		{"plankThickness", 0.2, "m", "plank extent along y"},
		{"plankDepth", 1, "m", "plank extent along z"},
		{"plankMass", 10, "kg", "mass of the plank"},
		{"boxSize", 0.5, "m", "cube edge"},
		{"boxMass", 1, "kg", "mass of each cube"},
		{"fulcrumSize", 0.5, "m", "edge of the static square prism, turned 45 degrees so an edge points up"},
		{"mu", 0.6, "-", build::kMuDescription},
	};
}

std::unique_ptr<SceneContent> createSeesaw(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int stack = build::countParam(params, "stack", 1);
	const btVector3 plankHalf = btScalar(0.5) * btVector3(build::positiveParam(params, "plankLength"), build::positiveParam(params, "plankThickness"), build::positiveParam(params, "plankDepth"));
	const btScalar plankMass = build::positiveParam(params, "plankMass");
	const btScalar boxHalf = build::positiveParam(params, "boxSize") / 2;
	const btScalar boxMass = build::positiveParam(params, "boxMass");
	const btScalar fulcrumHalf = build::positiveParam(params, "fulcrumSize") / 2;
	const btScalar mu = build::nonNegativeParam(params, "mu");
	build::require(plankHalf.x() > 2 * boxHalf, "plankLength must hold a cube at each end");

	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, 2 * plankHalf.x(), mu);

	// Turned 45 degrees, the prism's half diagonal fulcrumHalf * sqrt(2) stands between its centre and
	// its top edge; its bottom edge touches the ground.
	const btScalar halfDiagonal = fulcrumHalf * btSqrt(btScalar(2));
	const btScalar ridgeY = 2 * halfDiagonal;
	btCollisionShape* fulcrumShape = content->addShape(new btBoxShape(btVector3(fulcrumHalf, fulcrumHalf, plankHalf.z())));
	content->addBody(fulcrumShape, 0, build::rotatedAt(btVector3(0, 0, 1), SIMD_PI / 4, btVector3(0, halfDiagonal, 0)), mu);

	const btScalar plankY = build::columnCentreY(ridgeY, plankHalf.y(), 0);
	btCollisionShape* plankShape = content->addShape(new btBoxShape(plankHalf));
	content->name("plank", content->addBody(plankShape, plankMass, build::at(0, plankY, 0), mu));

	const btScalar plankTopY = plankY + plankHalf.y();
	const btScalar endX = plankHalf.x() - boxHalf;  // m, centre of a cube flush with a plank end
	btCollisionShape* boxShape = content->addShape(new btBoxShape(btVector3(boxHalf, boxHalf, boxHalf)));
	btRigidBody* heavyTop = nullptr;
	for (int level = 0; level < stack; ++level)
		heavyTop = content->addBody(boxShape, boxMass, build::at(-endX, build::columnCentreY(plankTopY, boxHalf, level), 0), mu);
	content->name("heavyTop", heavyTop);
	content->name("lightBox", content->addBody(boxShape, boxMass, build::at(endX, build::columnCentreY(plankTopY, boxHalf, 0), 0), mu));

	content->facts["heavySide"] = (stack > 1) ? -1 : 0;  // -1: the -x end goes down
	build::finishScene(*content, false);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// loaded_plank: a plank resting on two posts (dynamic, on the ground) with a heavy box off centre. Statics
// (lever rule): the support under x_s carries W_plank / 2 + W_load (1/2 + sign(x_s) x / span). The posts
// are thin along x, so where on a post's top the force acts changes the lever arms by at most
// postWidth / span (3% by default): wide supports make the split statically indeterminate.

Params loadedPlankParams()
{
	return {
		{"span", 3, "m", "distance between the support centres"},
		{"offset", 0.75, "m", "load centre's distance from the plank centre towards the right support"},
		{"plankLength", 4, "m", "plank extent along x"},
		{"plankThickness", 0.2, "m", "plank extent along y"},
		{"plankMass", 2, "kg", "mass of the plank"},
		{"loadMass", 5, "kg", "mass of the load box"},
		{"size", 0.5, "m", "edge of the load box; depth of the posts and of the plank"},
		{"postWidth", 0.1, "m", "post extent along x"},
		{"postHeight", 0.2, "m", "post extent along y"},
		{"supportMass", 1, "kg", "mass of each post"},
		{"mu", 0.6, "-", build::kMuDescription},
	};
}

std::unique_ptr<SceneContent> createLoadedPlank(btDiscreteDynamicsWorld& world, const Params& params)
{
	const btScalar span = build::positiveParam(params, "span");
	const btScalar offset = build::nonNegativeParam(params, "offset");
	const btScalar size = build::positiveParam(params, "size");
	const btScalar postWidth = build::positiveParam(params, "postWidth");
	const btScalar postHeight = build::positiveParam(params, "postHeight");
	const btVector3 plankHalf = btScalar(0.5) * btVector3(build::positiveParam(params, "plankLength"), build::positiveParam(params, "plankThickness"), size);
	const btScalar plankMass = build::positiveParam(params, "plankMass");
	const btScalar loadMass = build::positiveParam(params, "loadMass");
	const btScalar supportMass = build::positiveParam(params, "supportMass");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	build::require(span > postWidth + btScalar(build::kSideGap), "span must keep the posts apart");
	build::require(plankHalf.x() >= (span + postWidth) / 2, "plankLength must cover both posts");
	build::require(offset + size / 2 <= plankHalf.x(), "offset must keep the load on the plank");

	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, 2 * plankHalf.x(), mu);
	btCollisionShape* cubeShape = content->addShape(new btBoxShape(btVector3(size / 2, size / 2, size / 2)));
	btCollisionShape* postShape = content->addShape(new btBoxShape(btVector3(postWidth / 2, postHeight / 2, size / 2)));
	const btScalar supportY = build::columnCentreY(0, postHeight / 2, 0);
	content->name("leftSupport", content->addBody(postShape, supportMass, build::at(-span / 2, supportY, 0), mu));
	content->name("rightSupport", content->addBody(postShape, supportMass, build::at(span / 2, supportY, 0), mu));
	const btScalar plankY = build::columnCentreY(supportY + postHeight / 2, plankHalf.y(), 0);
	btCollisionShape* plankShape = content->addShape(new btBoxShape(plankHalf));
	content->name("plank", content->addBody(plankShape, plankMass, build::at(0, plankY, 0), mu));
	content->name("load", content->addBody(cubeShape, loadMass, build::at(offset, build::columnCentreY(plankY + plankHalf.y(), size / 2, 0), 0), mu));
	content->facts["rightShare"] = 0.5 + offset / span;  // share of the load on the right support
	build::finishScene(*content, true);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// friction_ramp: cubes side by side across a static ramp, cube k with friction mu_k from 0 to muMax; a
// cube slides exactly when mu_k < tan(angle). A static stop block past the ramp's foot catches the
// sliders (the mu = 0 cube would otherwise glide on for ever).

Params frictionRampParams()
{
	return {
		{"angleDeg", 20, "deg", "ramp inclination"},
		{"count", 6, "-", "cubes, side by side across the ramp"},
		{"muMax", 0.75, "-", "friction of the last cube (the first has 0, the others evenly between)"},
		{"rampLength", 6, "m", "ramp extent along its slope"},
		{"boxSize", 0.5, "m", "cube edge"},
		{"boxMass", 1, "kg", "mass of each cube"},
		{"runout", 2, "m", "distance along the ground from the ramp's foot to the stop block"},
	};
}

std::unique_ptr<SceneContent> createFrictionRamp(btDiscreteDynamicsWorld& world, const Params& params)
{
	const btScalar angle = build::degreesToRadians(build::positiveParam(params, "angleDeg"));
	const int count = build::countParam(params, "count", 1);
	const btScalar muMax = build::nonNegativeParam(params, "muMax");
	const btScalar rampHalfLength = build::positiveParam(params, "rampLength") / 2;
	const btScalar boxHalf = build::positiveParam(params, "boxSize") / 2;
	const btScalar boxMass = build::positiveParam(params, "boxMass");
	const btScalar runout = build::positiveParam(params, "runout");
	build::require(angle < SIMD_HALF_PI, "angleDeg must be below 90");
	build::require(rampHalfLength > 4 * boxHalf, "rampLength must be at least four cube edges");
	const btScalar rampHalfThickness = btScalar(0.1);  // m
	const btScalar lanePitch = 4 * boxHalf;            // m, across the ramp: one cube edge of space between lanes

	// The ramp and the ground have friction 1, so each pair combines to exactly the cube's own mu.
	const btScalar rampMu = 1;
	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, 4 * rampHalfLength + btScalar(count) * lanePitch, rampMu);

	// The slope descends towards +x and its top face meets the ground's top at its lower end.
	const btVector3 zAxis(0, 0, 1);
	const btScalar rampCentreY = rampHalfLength * btSin(angle) - rampHalfThickness * btCos(angle);
	const btTransform rampXf = build::rotatedAt(zAxis, -angle, btVector3(0, rampCentreY, 0));
	btCollisionShape* rampShape = content->addShape(new btBoxShape(btVector3(rampHalfLength, rampHalfThickness, btScalar(count) * lanePitch / 2)));
	content->addBody(rampShape, 0, rampXf, rampMu);

	// Stop block: a static wall one cube high across all lanes, `runout` past the foot of the slope.
	const btScalar footX = rampHalfLength * btCos(angle) + rampHalfThickness * btSin(angle);
	const btScalar stopX = footX + runout;  // m, its inner face
	const btVector3 stopHalf(boxHalf, 2 * boxHalf, btScalar(count) * lanePitch / 2);
	btCollisionShape* stopShape = content->addShape(new btBoxShape(stopHalf));
	content->addBody(stopShape, 0, build::at(stopX + stopHalf.x(), stopHalf.y(), 0), rampMu);

	btCollisionShape* boxShape = content->addShape(new btBoxShape(btVector3(boxHalf, boxHalf, boxHalf)));
	const btScalar startAlongSlope = -rampHalfLength / 2;  // m from the ramp centre, in its upper half
	const btScalar restHeight = rampHalfThickness + boxHalf - btScalar(build::kRestOverlap);  // m above the ramp's mid-plane
	for (int k = 0; k < count; ++k)
	{
		const btScalar mu = (count > 1) ? muMax * btScalar(k) / btScalar(count - 1) : 0;
		const btScalar laneZ = (btScalar(k) - btScalar(count - 1) / 2) * lanePitch;
		const btTransform xf(rampXf.getRotation(), rampXf * btVector3(startAlongSlope, restHeight, laneZ));
		btRigidBody* box = content->addBody(boxShape, boxMass, xf, mu);
		box->setFriction(mu);  // against friction 1, not sqrt(mu): the pair combines to exactly mu
		content->name("box" + std::to_string(k), box);
		content->facts["mu" + std::to_string(k)] = mu;
	}
	content->facts["angleRad"] = angle;
	content->facts["tanAngle"] = btTan(angle);
	content->facts["count"] = count;
	content->facts["stopX"] = stopX;
	build::finishScene(*content, false);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// domino_row: upright thin slabs in a row along +x; the first is tipped over its front edge and the
// chain reaction topples them all.

Params dominoRowParams()
{
	return {
		{"count", 15, "-", "number of dominoes"},
		{"spacing", 0.5, "m", "distance between neighbouring domino centres along x"},
		{"mu", 0.6, "-", build::kMuDescription},
		{"thickness", 0.1, "m", "domino extent along x"},
		{"height", 1, "m", "domino extent along y"},
		{"width", 0.5, "m", "domino extent along z"},
		{"mass", 1, "kg", "mass of each domino"},
		{"tipRate", 1, "rad/s", "initial angular speed of the first domino about its front bottom edge"},
		{"shape", 0, "-", "domino shape (0 box, 1 hull, 2 hull+features, 5 compound)"},
	};
}

std::unique_ptr<SceneContent> createDominoRow(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int count = build::countParam(params, "count", 1);
	const btScalar spacing = build::positiveParam(params, "spacing");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	const btVector3 half = btScalar(0.5) * btVector3(build::positiveParam(params, "thickness"), build::positiveParam(params, "height"), build::positiveParam(params, "width"));
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar tipRate = build::nonNegativeParam(params, "tipRate");
	const int shapeKind = build::countParam(params, "shape", 0);
	build::require(spacing > 2 * half.x() + btScalar(build::kSideGap), "spacing must exceed the domino thickness");
	build::require(shapeKind <= 2 || shapeKind == build::kCompound, "shape must be 0, 1, 2 or 5: a domino is a slab");

	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, 2 * btScalar(count) * spacing, mu);
	btCollisionShape* shape = build::addShapeOf(*content, shapeKind, half);
	const btScalar y = build::columnCentreY(0, half.y(), 0);
	const btScalar firstX = -btScalar(count - 1) * spacing / 2;
	btRigidBody* domino = nullptr;
	for (int i = 0; i < count; ++i)
	{
		domino = content->addBody(shape, mass, build::at(firstX + btScalar(i) * spacing, y, 0), mu);
		if (i == 0)
			content->name("first", domino);
	}
	content->name("last", domino);

	// Tip the first domino as a rigid rotation about its front (+x) bottom edge: omega about -z and the
	// matching centre velocity v = omega x (centre - edge).
	btRigidBody* first = content->named("first");
	const btVector3 omega(0, 0, -tipRate);
	const btVector3 edgeToCentre(-half.x(), half.y(), 0);
	first->setAngularVelocity(omega);
	first->setLinearVelocity(omega.cross(edgeToCentre));

	content->facts["spacing"] = spacing;
	content->facts["dominoHeight"] = 2 * half.y();
	build::finishScene(*content, false);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// hinge_bridge: planks chained by hinges between two static posts, hung with a little slack along a
// circular arc, with cubes resting on it; it sags to an equilibrium.

Params hingeBridgeParams()
{
	return {
		{"planks", 10, "-", "number of planks"},
		{"load", 3, "-", "cubes resting on the bridge, spread evenly"},
		{"plankLength", 1, "m", "plank extent along the bridge (hinge to hinge)"},
		{"plankThickness", 0.1, "m", "plank thickness"},
		{"plankWidth", 1, "m", "plank extent along z (the hinge axis)"},
		{"plankMass", 1, "kg", "mass of each plank"},
		{"loadSize", 0.3, "m", "edge of each load cube"},
		{"loadMass", 1, "kg", "mass of each load cube"},
		{"slack", 0.02, "-", "(chain length - span) / span"},
		{"deckHeight", 3, "m", "height of the end hinges on top of the posts"},
		{"mu", 0.6, "-", build::kMuDescription},
	};
}

std::unique_ptr<SceneContent> createHingeBridge(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int planks = build::countParam(params, "planks", 2);
	const int load = build::countParam(params, "load", 0);
	const btVector3 plankHalf = btScalar(0.5) * btVector3(build::positiveParam(params, "plankLength"), build::positiveParam(params, "plankThickness"), build::positiveParam(params, "plankWidth"));
	const btScalar plankMass = build::positiveParam(params, "plankMass");
	const btScalar loadHalf = build::positiveParam(params, "loadSize") / 2;
	const btScalar loadMass = build::positiveParam(params, "loadMass");
	const btScalar slack = build::nonNegativeParam(params, "slack");
	const btScalar deckHeight = build::positiveParam(params, "deckHeight");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	build::require(load <= planks, "load must not exceed planks (one cube per plank at most)");

	// Joint k (0..planks) lies on a circular arc of half angle phi through both post tops.
	const btScalar plankLength = 2 * plankHalf.x();
	const double phi = arcHalfAngle(planks, 1.0 / (1.0 + double(slack)));
	std::vector<btVector3> joints;
	btScalar sag = 0;  // m, initial depth of the lowest joint below the deck
	for (int k = 0; k <= planks; ++k)
	{
		if (phi == 0)
		{
			joints.emplace_back((btScalar(k) - btScalar(planks) / 2) * plankLength, deckHeight, 0);
			continue;
		}
		const double arcRadius = plankLength / (2 * std::sin(phi / planks));
		const double psi = -phi + 2 * phi * k / planks;  // rad, from straight down
		joints.emplace_back(btScalar(arcRadius * std::sin(psi)), btScalar(deckHeight + arcRadius * (std::cos(phi) - std::cos(psi))), 0);
		sag = btMax(sag, deckHeight - joints.back().y());
	}
	const btScalar span = joints.back().x() - joints.front().x();
	build::require(deckHeight > sag + 2 * plankHalf.y() + 2 * loadHalf, "deckHeight must keep the sagging bridge above the ground");

	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, 2 * span, mu);
	const btVector3 zAxis(0, 0, 1);

	// Posts: static columns whose inner top edges are the end joints.
	const btScalar postHalfWidth = btScalar(0.25);  // m
	btCollisionShape* postShape = content->addShape(new btBoxShape(btVector3(postHalfWidth, deckHeight / 2, plankHalf.z())));
	btRigidBody* leftPost = content->addBody(postShape, 0, build::at(joints.front().x() - postHalfWidth, deckHeight / 2, 0), mu);
	btRigidBody* rightPost = content->addBody(postShape, 0, build::at(joints.back().x() + postHalfWidth, deckHeight / 2, 0), mu);
	content->name("leftPost", leftPost);
	content->name("rightPost", rightPost);

	btCollisionShape* plankShape = content->addShape(new btBoxShape(plankHalf));
	std::vector<btRigidBody*> deck;
	for (int i = 0; i < planks; ++i)
	{
		const btVector3 along = joints[i + 1] - joints[i];
		const btScalar tilt = btAtan2(along.y(), along.x());
		deck.push_back(content->addBody(plankShape, plankMass, build::rotatedAt(zAxis, tilt, (joints[i] + joints[i + 1]) / 2), mu));
	}
	const btVector3 plankStart(-plankHalf.x(), 0, 0), plankEnd(plankHalf.x(), 0, 0);  // hinge points in plank frame
	content->addConstraint(new btHingeConstraint(*leftPost, *deck.front(), btVector3(postHalfWidth, deckHeight / 2, 0), plankStart, zAxis, zAxis));
	for (int i = 0; i + 1 < planks; ++i)
		content->addConstraint(new btHingeConstraint(*deck[i], *deck[i + 1], plankEnd, plankStart, zAxis, zAxis));
	content->addConstraint(new btHingeConstraint(*deck.back(), *rightPost, plankEnd, btVector3(-postHalfWidth, deckHeight / 2, 0), zAxis, zAxis));

	// Load cubes rest on evenly spread planks, tilted with them.
	btCollisionShape* loadShape = content->addShape(new btBoxShape(btVector3(loadHalf, loadHalf, loadHalf)));
	for (int j = 0; j < load; ++j)
	{
		const btTransform& plankXf = deck[size_t((j + 1) * planks / (load + 1))]->getWorldTransform();
		const btVector3 onPlank(0, plankHalf.y() + loadHalf - btScalar(build::kRestOverlap), 0);
		content->addBody(loadShape, loadMass, btTransform(plankXf.getRotation(), plankXf * onPlank), mu);
	}

	content->name("firstPlank", deck.front());
	content->name("middlePlank", deck[size_t(planks / 2)]);
	content->name("lastPlank", deck.back());
	content->facts["joints"] = planks + 1;
	content->facts["span"] = span;
	content->facts["deckHeight"] = deckHeight;
	content->facts["initialSag"] = sag;
	content->facts["plankLength"] = plankLength;
	build::finishScene(*content, false);
	return content;
}

}  // namespace scenes
