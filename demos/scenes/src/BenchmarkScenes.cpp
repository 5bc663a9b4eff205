// Layouts after Bullet's BenchmarkDemo and PyBullet's tests: leaning_columns (BenchmarkDemo's "3000
// boxes" staircases, fewer and shorter), boxes_3000 (the same at the demo's full size), stack_1000
// (BenchmarkDemo's "1000 stack": a pyramid, three walls and a round tower, 1076 cubes), ragdoll_pile
// (BenchmarkDemo's passive ragdolls, a small grid), heavy_top_column (PyBullet's column of unit cubes
// under a 1000x top cube) and flat_boxes (a cost baseline without stacks: one layer of boxes on the
// ground). Written from the published layouts (sizes, offsets, counts, joint limits); the construction
// is this project's.
//
// App facts: BenchmarkDemo (examples/Benchmarks/BenchmarkDemo.cpp, initPhysics) sets
// m_numIterations = 5 and SOLVER_ENABLE_FRICTION_DIRECTION_CACHING for its tests 1 to 3 ("3000
// boxes", "1000 stack", "Ragdolls"); the scenes after them record that as facts["appIterations"] and
// facts["appFrictionDirectionCaching"], so a benchmark can run the app's own solver settings.

#include "SceneBuild.h"
#include "SceneCatalog.h"

#include <cmath>
#include <string>

namespace scenes
{
namespace
{
/// The solver settings BenchmarkDemo's initPhysics asks for (tests 1 to 3).
void recordBenchmarkDemoSettings(SceneContent& content)
{
	content.facts["appIterations"] = 5;
	content.facts["appFrictionDirectionCaching"] = 1;
}
}  // namespace

// ---------------------------------------------------------------------------------------------------
// leaning_columns: BenchmarkDemo's "3000 boxes" (8 x 8 columns of 47 boxes of edge 2 m, layer pitch 3 m,
// each layer shifted 0.35 m further along -x and -z than the one below, dropped from 1 m gaps) at a
// grid and height a test can afford. Statics: within one column, the k boxes above a box have their
// centre of mass shift * (k + 1) / 2 past its centre along each of x and z; once that exceeds half
// the edge (k + 1 > edge / shift: from 5 boxes above, at the defaults) the column cannot stand.

Params leaningColumnsParams()
{
	return {
		{"columnsX", 2, "-", "columns along x"},
		{"columnsZ", 2, "-", "columns along z"},
		{"layers", 12, "-", "boxes per column"},
		{"size", 2, "m", "box edge (BenchmarkDemo: 2)"},
		{"shift", 0.35, "m", "shift of each layer along -x and -z relative to the one below (BenchmarkDemo: 0.35)"},
		{"gap", 1, "m", "vertical gap between layers and under the lowest one at the start (BenchmarkDemo: 1)"},
		{"spacing", 1, "m", "horizontal gap between neighbouring columns (BenchmarkDemo: 1)"},
		{"mass", 2, "kg", "mass of each box (BenchmarkDemo: 2)"},
		{"mu", 0.25, "-", "combined friction coefficient of every contact (Bullet's default 0.5 per body: 0.25)"},
	};
}

std::unique_ptr<SceneContent> createLeaningColumns(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int columnsX = build::countParam(params, "columnsX", 1);
	const int columnsZ = build::countParam(params, "columnsZ", 1);
	const int layers = build::countParam(params, "layers", 1);
	const btScalar size = build::positiveParam(params, "size");
	const btScalar shift = build::nonNegativeParam(params, "shift");
	const btScalar gap = build::nonNegativeParam(params, "gap");
	const btScalar spacing = build::nonNegativeParam(params, "spacing");
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	build::require(shift < size, "shift must be < size so each box lands on the one below");
	const btScalar half = size / 2;
	const btScalar pitch = size + spacing;  // m, column centre to column centre

	// Statics of one column (exact for boxes at rest on each other; the drop only adds motion).
	bool falls = false;
	for (int k = 1; k < layers; ++k)
		falls = falls || shift * btScalar(k + 1) / 2 > half;

	auto content = std::make_unique<SceneContent>(world);
	const btScalar extent = pitch * btScalar(btMax(columnsX, columnsZ)) + shift * btScalar(layers) + size * btScalar(layers);
	build::addGround(*content, 2 * extent, mu);
	btCollisionShape* shape = content->addShape(new btBoxShape(btVector3(half, half, half)));
	const btScalar x0 = -pitch * btScalar(columnsX - 1) / 2;
	const btScalar z0 = -pitch * btScalar(columnsZ - 1) / 2;
	double meanY = 0;
	for (int layer = 0; layer < layers; ++layer)
	{
		const btScalar y = gap + half + btScalar(layer) * (size + gap);
		const btScalar offset = -shift * btScalar(layer);
		for (int j = 0; j < columnsZ; ++j)
		{
			for (int i = 0; i < columnsX; ++i)
			{
				btRigidBody* box = content->addBody(shape, mass, build::at(x0 + pitch * btScalar(i) + offset, y, z0 + pitch * btScalar(j) + offset), mu);
				if (layer == layers - 1 && i == 0 && j == 0)
					content->name("top", box);
			}
			meanY += y * columnsX;
		}
	}
	content->facts["expectFalls"] = falls ? 1 : 0;
	content->facts["initialMeanHeight"] = meanY / double(layers * columnsX * columnsZ);  // m, centres
	content->facts["restingHeight"] = half;  // m, centre height of a box lying on the ground
	recordBenchmarkDemoSettings(*content);
	build::finishScene(*content, !falls);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// boxes_3000: BenchmarkDemo's "3000 boxes" (createTest1) at its own size: 8 x 8 columns of 47 cubes of
// edge 2 m and 2 kg (3008 bodies), layer pitch 3 m, each layer 0.35 m further along -x and -z, 1 m gaps.
// The construction and the statics are leaning_columns'; only the defaults differ.

Params boxes3000Params()
{
	return withOverrides(leaningColumnsParams(), {{"columnsX", 8}, {"columnsZ", 8}, {"layers", 47}});
}

std::unique_ptr<SceneContent> createBoxes3000(btDiscreteDynamicsWorld& world, const Params& params)
{
	return createLeaningColumns(world, params);
}

// ---------------------------------------------------------------------------------------------------
// ragdoll_pile: passive ragdolls (BenchmarkDemo's anatomy: 11 capsules of 1 kg, hinges at the waist,
// knees and elbows, cone-twist joints at the neck, hips and shoulders, the demo's joint limits and
// damping) standing upright in a grid of columns, dropped onto each other. Each one is tilted by
// `tilt` about a horizontal axis that turns from ragdoll to ragdoll (golden angle), so none starts
// in the (unstable) balanced pose. Physics: a passive ragdoll has no muscles: it folds and falls.

Params ragdollPileParams()
{
	return {
		{"columnsX", 2, "-", "ragdolls along x"},
		{"columnsZ", 2, "-", "ragdolls along z"},
		{"layers", 3, "-", "ragdolls stacked in each column, dropped onto each other"},
		{"scale", 1, "-", "size of a ragdoll (1: head centre 1.6 m above the pelvis' ground level)"},
		{"spacingX", 2, "m", "column pitch along x (arms span 1.73 m)"},
		{"spacingZ", 1, "m", "column pitch along z"},
		{"layerPitch", 2, "m", "height between stacked ragdolls"},
		{"lift", 0.05, "m", "gap under the feet of the lowest ragdolls"},
		{"tilt", 5, "deg", "initial lean of every ragdoll"},
		{"mu", 0.5, "-", build::kMuDescription},
	};
}

namespace
{
/// One capsule of the anatomy, in the ragdoll's own frame at scale 1 (feet near y = 0, facing +z).
struct Part
{
	const char* name;
	btScalar radius;
	btScalar height;   // m, cylinder part, along the capsule's local y
	btVector3 centre;
	btScalar rollZ;    // rad, rotation about z (arms lie along x)
};

enum PartIndex
{
	kPelvis, kSpine, kHead, kLeftUpperLeg, kLeftLowerLeg, kRightUpperLeg, kRightLowerLeg,
	kLeftUpperArm, kLeftLowerArm, kRightUpperArm, kRightLowerArm, kPartCount
};

const Part kParts[kPartCount] = {
	{"pelvis", btScalar(0.15), btScalar(0.20), btVector3(0, 1, 0), 0},
	{"spine", btScalar(0.15), btScalar(0.28), btVector3(0, btScalar(1.2), 0), 0},
	{"head", btScalar(0.10), btScalar(0.05), btVector3(0, btScalar(1.6), 0), 0},
	{"leftUpperLeg", btScalar(0.07), btScalar(0.45), btVector3(btScalar(-0.18), btScalar(0.65), 0), 0},
	{"leftLowerLeg", btScalar(0.05), btScalar(0.37), btVector3(btScalar(-0.18), btScalar(0.2), 0), 0},
	{"rightUpperLeg", btScalar(0.07), btScalar(0.45), btVector3(btScalar(0.18), btScalar(0.65), 0), 0},
	{"rightLowerLeg", btScalar(0.05), btScalar(0.37), btVector3(btScalar(0.18), btScalar(0.2), 0), 0},
	{"leftUpperArm", btScalar(0.05), btScalar(0.33), btVector3(btScalar(-0.35), btScalar(1.45), 0), SIMD_HALF_PI},
	{"leftLowerArm", btScalar(0.04), btScalar(0.25), btVector3(btScalar(-0.7), btScalar(1.45), 0), SIMD_HALF_PI},
	{"rightUpperArm", btScalar(0.05), btScalar(0.33), btVector3(btScalar(0.35), btScalar(1.45), 0), -SIMD_HALF_PI},
	{"rightLowerArm", btScalar(0.04), btScalar(0.25), btVector3(btScalar(0.7), btScalar(1.45), 0), -SIMD_HALF_PI},
};

/// Lowest point of the anatomy at scale 1 (bottom of the lower legs), m.
btScalar ragdollFootY() { return kParts[kLeftLowerLeg].centre.y() - kParts[kLeftLowerLeg].height / 2 - kParts[kLeftLowerLeg].radius; }

/// A joint frame at `anchor` (ragdoll frame, scale 1) whose x axis is `xAxis` (unit), expressed in the
/// frame of a part whose rest pose in the ragdoll frame is `part`. Built at the rest pose, so both
/// bodies' frames coincide in the world and no joint starts with an error.
btTransform jointFrameIn(const btTransform& part, const btVector3& anchor, const btVector3& xAxis)
{
	// A rotation taking x to xAxis: about x cross xAxis (or any perpendicular axis if they are opposite).
	const btVector3 x(1, 0, 0);
	btQuaternion q = btQuaternion::getIdentity();
	const btVector3 c = x.cross(xAxis);
	const btScalar d = x.dot(xAxis);
	if (c.length2() > btScalar(1e-12))
		q = btQuaternion(c.normalized(), btAcos(btMax(btScalar(-1), btMin(btScalar(1), d))));
	else if (d < 0)
		q = btQuaternion(btVector3(0, 0, 1), SIMD_PI);
	return part.inverse() * btTransform(q, anchor);
}
}  // namespace

std::unique_ptr<SceneContent> createRagdollPile(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int columnsX = build::countParam(params, "columnsX", 1);
	const int columnsZ = build::countParam(params, "columnsZ", 1);
	const int layers = build::countParam(params, "layers", 1);
	const btScalar scale = build::positiveParam(params, "scale");
	const btScalar spacingX = build::positiveParam(params, "spacingX");
	const btScalar spacingZ = build::positiveParam(params, "spacingZ");
	const btScalar layerPitch = build::positiveParam(params, "layerPitch");
	const btScalar lift = build::nonNegativeParam(params, "lift");
	const btScalar tilt = build::degreesToRadians(build::nonNegativeParam(params, "tilt"));
	const btScalar mu = build::nonNegativeParam(params, "mu");
	build::require(layerPitch > btScalar(1.8) * scale, "layerPitch must clear a standing ragdoll (1.8 m at scale 1)");

	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, spacingX * btScalar(columnsX) + spacingZ * btScalar(columnsZ), mu);

	btCollisionShape* shapes[kPartCount];
	btTransform rest[kPartCount];  // part poses in the ragdoll frame, at `scale`
	for (int p = 0; p < kPartCount; ++p)
	{
		shapes[p] = content->addShape(new btCapsuleShape(kParts[p].radius * scale, kParts[p].height * scale));
		rest[p] = btTransform(btQuaternion(btVector3(0, 0, 1), kParts[p].rollZ), kParts[p].centre * scale);
	}

	// Joints: anchors between the capsules' ends (ragdoll frame, scale 1); hinge axes are the frame's z,
	// cone-twist (twist) axes its x. Limits are BenchmarkDemo's.
	struct Joint
	{
		int a, b;
		bool hinge;
		btVector3 anchor;
		btVector3 axis;      // hinge axis (z of the frame) or twist axis (x of the frame)
		btScalar l0, l1, l2; // hinge: low, high; cone twist: swing span 1, swing span 2, twist span
	};
	const btScalar q = SIMD_PI / 4, h = SIMD_HALF_PI;
	const Joint joints[] = {
		{kPelvis, kSpine, true, btVector3(0, btScalar(1.10), 0), btVector3(1, 0, 0), -q, h, 0},
		{kSpine, kHead, false, btVector3(0, btScalar(1.48), 0), btVector3(0, 1, 0), q, q, h},
		{kPelvis, kLeftUpperLeg, false, btVector3(btScalar(-0.18), btScalar(0.89), 0), btVector3(0, -1, 0), q, q, 0},
		{kLeftUpperLeg, kLeftLowerLeg, true, btVector3(btScalar(-0.18), btScalar(0.405), 0), btVector3(1, 0, 0), 0, h, 0},
		{kPelvis, kRightUpperLeg, false, btVector3(btScalar(0.18), btScalar(0.89), 0), btVector3(0, -1, 0), q, q, 0},
		{kRightUpperLeg, kRightLowerLeg, true, btVector3(btScalar(0.18), btScalar(0.405), 0), btVector3(1, 0, 0), 0, h, 0},
		{kSpine, kLeftUpperArm, false, btVector3(btScalar(-0.18), btScalar(1.45), 0), btVector3(-1, 0, 0), h, h, 0},
		{kLeftUpperArm, kLeftLowerArm, true, btVector3(btScalar(-0.545), btScalar(1.45), 0), btVector3(0, 1, 0), 0, h, 0},
		{kSpine, kRightUpperArm, false, btVector3(btScalar(0.18), btScalar(1.45), 0), btVector3(1, 0, 0), h, h, 0},
		{kRightUpperArm, kRightLowerArm, true, btVector3(btScalar(0.545), btScalar(1.45), 0), btVector3(0, 1, 0), 0, h, 0},
	};

	const btScalar golden = SIMD_PI * (3 - btSqrt(btScalar(5)));  // rad, golden angle
	const btScalar baseY = (lift - ragdollFootY()) * scale;
	int index = 0;
	for (int layer = 0; layer < layers; ++layer)
	{
		for (int j = 0; j < columnsZ; ++j)
		{
			for (int i = 0; i < columnsX; ++i, ++index)
			{
				const btVector3 origin(spacingX * (btScalar(i) - btScalar(columnsX - 1) / 2), baseY + layerPitch * btScalar(layer),
									   spacingZ * (btScalar(j) - btScalar(columnsZ - 1) / 2));
				const btScalar heading = golden * btScalar(index);
				const btVector3 leanAxis(btCos(heading), 0, btSin(heading));
				const btTransform place(btQuaternion(leanAxis, tilt), origin);
				btRigidBody* bodies[kPartCount];
				for (int p = 0; p < kPartCount; ++p)
				{
					bodies[p] = content->addBody(shapes[p], 1, place * rest[p], mu);
					bodies[p]->setDamping(btScalar(0.05), btScalar(0.85));  // BenchmarkDemo's ragdoll damping
				}
				content->name("head" + std::to_string(index), bodies[kHead]);
				content->name("pelvis" + std::to_string(index), bodies[kPelvis]);
				for (const Joint& jt : joints)
				{
					const btVector3 anchor = jt.anchor * scale;
					if (jt.hinge)
					{
						// The hinge axis is the frame's z: a frame whose x is perpendicular to it, turned so z = axis.
						const btVector3 x = (std::fabs(jt.axis.y()) > btScalar(0.5)) ? btVector3(1, 0, 0) : btVector3(0, 1, 0);
						const btVector3 y = jt.axis.cross(x);
						btMatrix3x3 basis(x.x(), y.x(), jt.axis.x(), x.y(), y.y(), jt.axis.y(), x.z(), y.z(), jt.axis.z());
						const btTransform frame(basis, anchor);
						auto* c = new btHingeConstraint(*bodies[jt.a], *bodies[jt.b], rest[jt.a].inverse() * frame, rest[jt.b].inverse() * frame);
						c->setLimit(jt.l0, jt.l1);
						content->addConstraint(c, true);
					}
					else
					{
						auto* c = new btConeTwistConstraint(*bodies[jt.a], *bodies[jt.b], jointFrameIn(rest[jt.a], anchor, jt.axis),
															jointFrameIn(rest[jt.b], anchor, jt.axis));
						c->setLimit(jt.l0, jt.l1, jt.l2);
						content->addConstraint(c, true);
					}
				}
			}
		}
	}
	content->facts["ragdolls"] = index;
	content->facts["standingHeadHeight"] = (kParts[kHead].centre.y() - ragdollFootY()) * scale;  // m, head centre over the soles
	recordBenchmarkDemoSettings(*content);
	build::finishScene(*content, false);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// heavy_top_column: PyBullet's case, a column of n unit cubes whose top cube is `ratio` times heavier,
// each resting on the one below. Statics: aligned, it stands; nothing in it may gain energy.

Params heavyTopColumnParams()
{
	return {
		{"n", 10, "-", "number of cubes, the heavy one included"},
		{"ratio", 1000, "-", "mass of the top cube / mass of each other cube"},
		{"size", 1, "m", "cube edge"},
		{"mass", 1, "kg", "mass of each light cube"},
		{"mu", 0.6, "-", build::kMuDescription},
	};
}

std::unique_ptr<SceneContent> createHeavyTopColumn(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int n = build::countParam(params, "n", 2);
	const btScalar ratio = build::positiveParam(params, "ratio");
	const btScalar size = build::positiveParam(params, "size");
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	const btScalar half = size / 2;

	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, 4 * size * btScalar(n), mu);
	btCollisionShape* shape = content->addShape(new btBoxShape(btVector3(half, half, half)));
	for (int level = 0; level < n; ++level)
	{
		const bool isTop = (level == n - 1);
		btRigidBody* cube = content->addBody(shape, isTop ? ratio * mass : mass, build::at(0, build::columnCentreY(0, half, level), 0), mu);
		if (level == 0)
			content->name("bottom", cube);
		if (isTop)
			content->name("top", cube);
	}
	content->facts["ratio"] = ratio;
	content->facts["topMass"] = ratio * mass;  // kg
	build::finishScene(*content, true);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// stack_1000: BenchmarkDemo's "1000 stack" (createTest2), 1076 cubes of edge 2 m and 1 kg in three
// groups side by side along x:
// - a square pyramid of 12 layers (12 x 12 at the bottom up to 1 x 1: 650 cubes), neighbours 1.02 edges
//   apart (4 cm gaps), each layer centred on the four-cube junctions of the one below;
// - three walls of 12 rows along z (12 cubes at the bottom up to 1: 78 each), each row shifted half a
//   cube, the walls 6 m apart along x;
// - a round tower of 8 rings of 24 cubes on a circle of radius 1.3 * 24 * (edge / 2) / pi (9.93 m),
//   every cube facing the centre, each ring turned half a cube (pi / 24) against the one below.
// The demo places the groups at x = -20 (pyramid), -2, 4, 10 (walls) and 25 (tower); here the groups
// keep the demo's order and distances between footprints but are placed from their sizes, so no
// instance overlaps. The project's conventions replace the demo's exact touching (walls, rings) and
// its 4 cm vertical gaps (pyramid): rows rest 10 micrometres deep in the row below and wall neighbours
// keep 1 mm. Statics: every cube rests centred on four (pyramid) or across two (walls, rings) cubes
// below, so everything stands.

Params stack1000Params()
{
	return {
		{"pyramid", 12, "-", "layers of the pyramid (0: none; BenchmarkDemo: 12, 650 cubes)"},
		{"walls", 3, "-", "number of walls (BenchmarkDemo: 3)"},
		{"wallRows", 12, "-", "rows of each wall, as many cubes in the lowest (BenchmarkDemo: 12, 78 cubes)"},
		{"rings", 8, "-", "rings of the round tower (0: none; BenchmarkDemo: 8)"},
		{"ringCubes", 24, "-", "cubes per ring (BenchmarkDemo: 24)"},
		{"size", 2, "m", "cube edge (BenchmarkDemo: 2)"},
		{"mass", 1, "kg", "mass of each cube (BenchmarkDemo: 1)"},
		{"mu", 0.25, "-", "combined friction coefficient of every contact (Bullet's default 0.5 per body: 0.25)"},
	};
}

std::unique_ptr<SceneContent> createStack1000(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int pyramid = build::countParam(params, "pyramid", 0);
	const int walls = build::countParam(params, "walls", 0);
	const int wallRows = build::countParam(params, "wallRows", 1);
	const int rings = build::countParam(params, "rings", 0);
	const int ringCubes = build::countParam(params, "ringCubes", 3);
	const btScalar size = build::positiveParam(params, "size");
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	build::require(pyramid + walls + rings > 0, "at least one of pyramid, walls, rings must be > 0");
	const btScalar half = size / 2;
	const btScalar radius = btScalar(1.3) * btScalar(ringCubes) * half / SIMD_PI;  // m, BenchmarkDemo's ring radius
	// Neighbouring cubes of a ring must not touch at their inner corners.
	build::require(btAtan2(half + btScalar(build::kSideGap), radius - half) < SIMD_PI / btScalar(ringCubes),
				   "ringCubes too small: neighbouring cubes of a ring would overlap at their inner corners");

	// Footprints along x, in the demo's order, with the demo's clearances (m).
	const btScalar pyramidPitch = btScalar(1.02) * size + btScalar(1e-4);  // BenchmarkDemo's spacing
	const btScalar pyramidWidth = pyramid > 0 ? pyramidPitch * btScalar(pyramid - 1) + size : 0;
	const btScalar wallPitchX = 3 * size;  // walls 6 m apart at the demo's size
	const btScalar wallsWidth = walls > 0 ? wallPitchX * btScalar(walls - 1) + size : 0;
	const btScalar towerWidth = rings > 0 ? 2 * (radius + half) : 0;
	const btScalar clearPyramidWall = btScalar(2.9) * size;  // demo: 5.8 m
	const btScalar clearWallTower = btScalar(1.5) * size;    // demo: about 3 m
	const btScalar total = pyramidWidth + clearPyramidWall + wallsWidth + clearWallTower + towerWidth;
	btScalar left = -total / 2;

	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, total, mu);
	btCollisionShape* shape = content->addShape(new btBoxShape(btVector3(half, half, half)));
	int pyramidCubes = 0, wallCubes = 0, towerCubes = 0;

	// The pyramid: layer k is (pyramid - k) x (pyramid - k), centred on the same vertical axis.
	const btScalar pyramidX = left + pyramidWidth / 2;
	for (int k = 0; k < pyramid; ++k)
	{
		const int n = pyramid - k;
		const btScalar y = build::columnCentreY(0, half, k);
		for (int j = 0; j < n; ++j)
		{
			for (int i = 0; i < n; ++i)
			{
				const btScalar x = pyramidX + pyramidPitch * (btScalar(i) - btScalar(n - 1) / 2);
				const btScalar z = pyramidPitch * (btScalar(j) - btScalar(n - 1) / 2);
				btRigidBody* cube = content->addBody(shape, mass, build::at(x, y, z), mu);
				++pyramidCubes;
				if (k == pyramid - 1)
					content->name("pyramidTop", cube);
			}
		}
	}
	if (pyramid > 0)
		left += pyramidWidth + clearPyramidWall;

	// The walls: row r has wallRows - r cubes along z, centred, so each rests across two of the row below.
	const btScalar wallPitchZ = size + btScalar(build::kSideGap);
	for (int w = 0; w < walls; ++w)
	{
		const btScalar x = left + half + wallPitchX * btScalar(w);
		for (int r = 0; r < wallRows; ++r)
		{
			const int n = wallRows - r;
			const btScalar y = build::columnCentreY(0, half, r);
			for (int i = 0; i < n; ++i)
			{
				btRigidBody* cube = content->addBody(shape, mass, build::at(x, y, wallPitchZ * (btScalar(i) - btScalar(n - 1) / 2)), mu);
				++wallCubes;
				if (w == 0 && r == wallRows - 1)
					content->name("wallTop", cube);
			}
		}
	}
	if (walls > 0)
		left += wallsWidth + clearWallTower;

	// The round tower: cube j of ring r at angle (j + r / 2) * 2 pi / ringCubes, facing the centre.
	const btScalar towerX = left + towerWidth / 2;
	for (int r = 0; r < rings; ++r)
	{
		const btScalar y = build::columnCentreY(0, half, r);
		for (int j = 0; j < ringCubes; ++j)
		{
			const btScalar angle = (btScalar(j) + btScalar(r % 2) / 2) * SIMD_2_PI / btScalar(ringCubes);
			const btVector3 centre(towerX + radius * btSin(angle), y, radius * btCos(angle));
			btRigidBody* cube = content->addBody(shape, mass, build::rotatedAt(btVector3(0, 1, 0), angle, centre), mu);
			++towerCubes;
			if (r == rings - 1 && j == 0)
				content->name("towerTop", cube);
		}
	}

	content->facts["pyramidCubes"] = pyramidCubes;
	content->facts["wallCubes"] = wallCubes;
	content->facts["towerCubes"] = towerCubes;
	content->facts["ringRadius"] = radius;  // m
	recordBenchmarkDemoSettings(*content);
	build::finishScene(*content, true);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// flat_boxes: the cost baseline without stacks: a grid of cubes resting side by side on the ground,
// one layer, every cube its own island. With v0 > 0 each cube slides along +x and Coulomb friction
// stops it after v0^2 / (2 mu g); with v0 = 0 nothing moves.

Params flatBoxesParams()
{
	return {
		{"countX", 20, "-", "cubes along x"},
		{"countZ", 20, "-", "cubes along z"},
		{"size", 1, "m", "cube edge"},
		{"gap", 0.5, "m", "gap between neighbouring cubes"},
		{"v0", 0, "m/s", "initial speed of every cube along +x (0: at rest)"},
		{"mass", 1, "kg", "mass of each cube"},
		{"mu", 0.5, "-", build::kMuDescription},
	};
}

std::unique_ptr<SceneContent> createFlatBoxes(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int countX = build::countParam(params, "countX", 1);
	const int countZ = build::countParam(params, "countZ", 1);
	const btScalar size = build::positiveParam(params, "size");
	const btScalar gap = build::nonNegativeParam(params, "gap");
	const btScalar v0 = build::nonNegativeParam(params, "v0");
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	build::require(gap >= btScalar(build::kSideGap), "gap must be at least 1 mm");
	const btScalar half = size / 2;
	const btScalar pitch = size + gap;

	auto content = std::make_unique<SceneContent>(world);
	// Room for the slide: v0^2 / (2 mu g) at g = 9.81 (any mu > 0.01).
	const btScalar slide = v0 * v0 / (2 * btMax(mu, btScalar(0.01)) * btScalar(9.81));
	build::addGround(*content, pitch * btScalar(btMax(countX, countZ)) + slide, mu);
	btCollisionShape* shape = content->addShape(new btBoxShape(btVector3(half, half, half)));
	const btScalar y = build::columnCentreY(0, half, 0);
	for (int j = 0; j < countZ; ++j)
	{
		for (int i = 0; i < countX; ++i)
		{
			btRigidBody* cube = content->addBody(shape, mass, build::at(pitch * (btScalar(i) - btScalar(countX - 1) / 2), y, pitch * (btScalar(j) - btScalar(countZ - 1) / 2)), mu);
			cube->setLinearVelocity(btVector3(v0, 0, 0));
			if (i == 0 && j == 0)
				content->name("first", cube);
		}
	}
	content->facts["v0"] = v0;
	content->facts["mu"] = mu;
	build::finishScene(*content, v0 == 0);
	return content;
}

}  // namespace scenes
