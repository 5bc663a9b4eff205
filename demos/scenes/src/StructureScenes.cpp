// Structures apps build from shapes other than a column of equal boxes (issue 37): a table made as
// a compound carrying a stack, a crib of interlocking planks, and a bin of random convex hulls. Each
// takes the shape grid's "ground" parameter (src/ShapeKinds.cpp).

#include "SceneBuild.h"
#include "SceneCatalog.h"

#include <cmath>
#include <random>

namespace scenes
{
namespace
{
/// Inertia of a solid box of half extents h and mass m about its centre (diagonal).
btVector3 boxInertia(const btVector3& h, btScalar m)
{
	return btScalar(4) * m / btScalar(12) * btVector3(h.y() * h.y() + h.z() * h.z(), h.x() * h.x() + h.z() * h.z(), h.x() * h.x() + h.y() * h.y());
}

}  // namespace

// ---------------------------------------------------------------------------------------------------
// table_stack: a table made as one btCompoundShape body (a top slab and four legs, uniform density,
// its frame at its centre of mass so Bullet's body frame is the true one) standing on the ground,
// carrying a column of n standard boxes (1 x 0.5 x 1 m, 1 kg) `offset` from the middle of its top
// (1.6 m square). Within 0.8 m the column's centre of mass is over the top: in equilibrium, so
// everything stays at rest (the fact "expectStanding"); beyond, the column tips over the top's edge
// and falls off (the table itself stays: with 5 boxes at offset 1 m their common centre of mass is
// 0.33 m from the middle, inside the legs). The table's inertia is the parts' (parallel axes), not
// Bullet's bounding-box estimate for a compound.

Params tableStackParams()
{
	return {
		{"n", 5, "-", "boxes stacked on the table"},
		{"offset", 0, "m", "the column's offset along x from the middle of the table top (0.8 m: the top's edge)"},
		{"tableMass", 10, "kg", "mass of the table"},
		{"ground", 0, "-", "ground (0 box, 1 plane, 2 triangle mesh, 3 mesh+internal edges, 4 heightfield)"},
		{"mu", 0.6, "-", build::kMuDescription},
	};
}

std::unique_ptr<SceneContent> createTableStack(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int n = build::countParam(params, "n", 0);
	const btScalar offset = btScalar(getParam(params, "offset"));
	const btScalar tableMass = build::positiveParam(params, "tableMass");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	const btVector3 topHalf(btScalar(0.8), btScalar(0.05), btScalar(0.8));
	const btVector3 legHalf(btScalar(0.05), btScalar(0.45), btScalar(0.05));
	const btScalar legInset = btScalar(0.7);                    // m, leg axis from the table's centre line
	const btScalar height = 2 * (topHalf.y() + legHalf.y());  // m, floor to table top

	// Part centres in a frame whose origin is on the floor under the table's middle; masses by volume.
	const btScalar topVolume = topHalf.x() * topHalf.y() * topHalf.z(), legVolume = legHalf.x() * legHalf.y() * legHalf.z();
	const btScalar density = tableMass / (topVolume + 4 * legVolume);  // per 1/8 m^3
	const btScalar topMass = density * topVolume, legMass = density * legVolume;
	const btVector3 topCentre(0, height - topHalf.y(), 0);
	btVector3 legCentres[4];
	for (int i = 0; i < 4; ++i) legCentres[i] = btVector3((i & 1) ? legInset : -legInset, legHalf.y(), (i & 2) ? legInset : -legInset);
	btVector3 com = topCentre * topMass;
	for (const btVector3& c : legCentres) com += c * legMass;
	com /= tableMass;

	auto content = std::make_unique<SceneContent>(world);
	build::addGroundOf(*content, build::countParam(params, "ground", 0), 2 * topHalf.x(), mu);
	btCompoundShape* compound = new btCompoundShape();
	btCollisionShape* top = content->addShape(new btBoxShape(topHalf));
	btCollisionShape* leg = content->addShape(new btBoxShape(legHalf));
	compound->addChildShape(build::at(topCentre.x(), topCentre.y() - com.y(), topCentre.z()), top);
	btVector3 inertia = boxInertia(topHalf, topMass) + topMass * btVector3((topCentre - com).length2() - (topCentre - com).x() * (topCentre - com).x(),
																		   (topCentre - com).length2() - (topCentre - com).y() * (topCentre - com).y(),
																		   (topCentre - com).length2() - (topCentre - com).z() * (topCentre - com).z());
	for (const btVector3& c : legCentres)
	{
		const btVector3 r = c - com;
		compound->addChildShape(build::at(r.x(), r.y(), r.z()), leg);
		inertia += boxInertia(legHalf, legMass) + legMass * btVector3(r.length2() - r.x() * r.x(), r.length2() - r.y() * r.y(), r.length2() - r.z() * r.z());
	}
	btRigidBody* table = content->addBody(content->addShape(compound), tableMass, build::at(0, com.y() - btScalar(build::kRestOverlap), 0), mu);
	table->setMassProps(tableMass, inertia);
	table->updateInertiaTensor();
	content->name("table", table);
	content->name("bottom", table);

	const btVector3 boxHalf = build::standardBoxHalfExtents();
	btCollisionShape* box = content->addShape(new btBoxShape(boxHalf));
	const btScalar base = height - 2 * btScalar(build::kRestOverlap);
	btRigidBody* body = table;
	for (int level = 0; level < n; ++level) body = content->addBody(box, 1, build::at(offset, build::columnCentreY(base, boxHalf.y(), level), 0), mu);
	content->name("top", body);
	content->facts["tableTop"] = height;
	build::finishScene(*content, btFabs(offset) < topHalf.x());
	return content;
}

// ---------------------------------------------------------------------------------------------------
// plank_crib: a crib of interlocking planks (a log-cabin stack): `layers` layers of two planks
// (length x section x section), each layer turned 90 degrees from the one below, the planks of a
// layer `spread` apart, so each plank rests on the two planks below it at two square crossings. In
// equilibrium (every plank's weight between its two supports), so it stands.

Params plankCribParams()
{
	return {
		{"layers", 10, "-", "layers of two planks"},
		{"length", 3, "m", "plank length"},
		{"section", 0.3, "m", "plank width and thickness"},
		{"spread", 2.4, "m", "distance between the two planks of a layer (axis to axis)"},
		{"mass", 5, "kg", "mass of each plank"},
		{"shape", 0, "-", "plank shape (0 box, 1 hull of the box's corners)"},
		{"ground", 0, "-", "ground (0 box, 1 plane, 2 triangle mesh, 3 mesh+internal edges, 4 heightfield)"},
		{"mu", 0.6, "-", build::kMuDescription},
	};
}

std::unique_ptr<SceneContent> createPlankCrib(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int layers = build::countParam(params, "layers", 1);
	const btScalar length = build::positiveParam(params, "length");
	const btScalar section = build::positiveParam(params, "section");
	const btScalar spread = build::positiveParam(params, "spread");
	const btScalar mass = build::positiveParam(params, "mass");
	const int shapeKind = build::countParam(params, "shape", 0);
	const btScalar mu = build::nonNegativeParam(params, "mu");
	build::require(shapeKind == build::kBox || shapeKind == build::kHull, "shape must be 0 (box) or 1 (hull)");
	build::require(spread + section < length, "spread + section must be below the length: each plank must reach both planks under it");

	auto content = std::make_unique<SceneContent>(world);
	build::addGroundOf(*content, build::countParam(params, "ground", 0), length, mu);
	const btVector3 halfAlongX(length / 2, section / 2, section / 2);
	btCollisionShape* alongX = build::addShapeOf(*content, shapeKind, halfAlongX);
	btCollisionShape* alongZ = build::addShapeOf(*content, shapeKind, btVector3(section / 2, section / 2, length / 2));
	btRigidBody* body = nullptr;
	for (int layer = 0; layer < layers; ++layer)
	{
		const btScalar y = build::columnCentreY(0, section / 2, layer);
		for (int side = 0; side < 2; ++side)
		{
			const btScalar offset = (side ? btScalar(0.5) : btScalar(-0.5)) * spread;
			body = content->addBody(layer % 2 ? alongZ : alongX, mass, layer % 2 ? build::at(offset, y, 0) : build::at(0, y, offset), mu);
			if (layer == 0 && side == 0) content->name("bottom", body);
		}
	}
	content->name("top", body);
	build::finishScene(*content, true);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// hull_bin: `count` random convex hulls (each the hull of 12 points drawn on an ellipsoid of
// semi-axes 0.15-0.3 m, seeded) dropped from a loose grid into a square bin of four static walls on
// the ground: they fall, collide and settle into a pile that comes to rest.

Params hullBinParams()
{
	return {
		{"count", 30, "-", "number of hulls"},
		{"seed", 1, "-", "seed of the std::mt19937 that draws the hulls, offsets and rotations"},
		{"width", 2.5, "m", "inner side of the square bin"},
		{"mass", 1, "kg", "mass of each hull"},
		{"ground", 0, "-", "ground (0 box, 1 plane, 2 triangle mesh, 3 mesh+internal edges, 4 heightfield)"},
		{"mu", 0.6, "-", build::kMuDescription},
	};
}

std::unique_ptr<SceneContent> createHullBin(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int count = build::countParam(params, "count", 1);
	std::mt19937 rng(build::seedParam(params));
	const btScalar width = build::positiveParam(params, "width");
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	auto uniform = [&](double low, double high) { return btScalar(low + (high - low) * (double(rng()) / 4294967296.0)); };
	const btScalar largest = btScalar(0.3);                   // m, largest semi-axis
	const btScalar cell = 2 * largest * btScalar(1.1);       // m, grid cell: a hull in any rotation fits
	const int perSide = int(std::floor(width / cell));
	build::require(perSide >= 1, "width must hold one hull (0.66 m)");
	const int perLayer = perSide * perSide;
	const int gridLayers = (count + perLayer - 1) / perLayer;
	const btScalar dropHeight = btScalar(0.5);
	const btScalar wallHalfHeight = (dropHeight + btScalar(gridLayers) * cell) / 2;

	auto content = std::make_unique<SceneContent>(world);
	build::addGroundOf(*content, build::countParam(params, "ground", 0), 2 * width, mu);
	build::addSquarePit(*content, width, wallHalfHeight, mu);

	const btScalar firstCell = -btScalar(perSide - 1) * cell / 2;
	for (int i = 0; i < count; ++i)
	{
		const btVector3 axes(uniform(0.15, 0.3), uniform(0.15, 0.3), uniform(0.15, 0.3));
		btConvexHullShape* hull = new btConvexHullShape();
		for (int k = 0; k < 12; ++k)
		{
			// A direction uniform on the sphere, scaled onto the ellipsoid.
			const btScalar z = uniform(-1, 1), phi = uniform(0, 2 * SIMD_PI), r = btSqrt(btMax(btScalar(0), 1 - z * z));
			hull->addPoint(btVector3(r * btCos(phi) * axes.x(), r * btSin(phi) * axes.y(), z * axes.z()), false);
		}
		hull->recalcLocalAabb();
		const int layer = i / perLayer, column = (i % perLayer) % perSide, row = (i % perLayer) / perSide;
		const btVector3 centre(firstCell + btScalar(column) * cell, dropHeight + (btScalar(layer) + btScalar(0.5)) * cell, firstCell + btScalar(row) * cell);
		btVector3 axis(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
		if (!(axis.length2() > btScalar(1e-6))) axis = btVector3(0, 1, 0);
		const btQuaternion rotation(axis.normalized(), uniform(0, 2 * SIMD_PI));
		content->addBody(content->addShape(hull), mass, btTransform(rotation, centre), mu);
	}
	content->facts["width"] = width;
	build::finishScene(*content, false);
	return content;
}

}  // namespace scenes
