// Layouts after Bullet's BenchmarkDemo and PyBullet's tests, at a size a test can run: leaning_columns
// (BenchmarkDemo's "3000 boxes" staircases, fewer and shorter), ragdoll_pile (BenchmarkDemo's passive
// ragdolls, a small grid) and heavy_top_column (PyBullet's column of unit cubes under a 1000x top cube).
// Written from the published layouts (sizes, offsets, joint limits); the construction is this project's.

#include "SceneBuild.h"
#include "SceneCatalog.h"

#include <cmath>
#include <string>

namespace scenes
{
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
	build::finishScene(*content, !falls);
	return content;
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

}  // namespace scenes
