// Masonry, where the stability depends on friction and on the way blocks interlock: wall, round_tower,
// door, arch, card_house.

#include "SceneBuild.h"
#include "SceneCatalog.h"

namespace scenes
{
namespace
{
/// Area (m^2) and centroid of a simple polygon in the x-y plane, counter-clockwise.
void polygonAreaCentroid(const std::vector<btVector3>& polygon, btScalar& area, btVector3& centroid)
{
	btScalar twiceArea = 0;
	btVector3 weighted(0, 0, 0);
	for (size_t i = 0; i < polygon.size(); ++i)
	{
		const btVector3& p = polygon[i];
		const btVector3& q = polygon[(i + 1) % polygon.size()];
		const btScalar cross = p.x() * q.y() - q.x() * p.y();
		twiceArea += cross;
		weighted += (p + q) * cross;
	}
	area = twiceArea / 2;
	centroid = weighted / (3 * twiceArea);
}

}  // namespace

// ---------------------------------------------------------------------------------------------------
// wall: running-bond brick wall in the x-y plane; even rows have `length` bricks, odd rows are shifted
// by half a brick: with half bricks at their ends (default; 16 rows of 12 bricks and of 11 bricks plus
// two halves make 200 pieces, both wall ends flush) or one brick shorter (halfBricks=0, length=13:
// 200 bricks whose long rows' end bricks overhang by half a brick).

Params wallParams()
{
	return {
		{"rows", 16, "-", "number of brick rows"},
		{"length", 12, "-", "bricks in an even row (odd rows: one fewer, plus two half bricks if halfBricks=1)"},
		{"brickLength", 0.4, "m", "brick extent along x"},
		{"brickHeight", 0.2, "m", "brick extent along y"},
		{"brickDepth", 0.2, "m", "brick extent along z"},
		{"mass", 1, "kg", "mass of each brick"},
		{"mu", 0.6, "-", build::kMuDescription},
		{"gap", build::kSideGap, "m", "horizontal gap between neighbouring bricks"},
		{"halfBricks", 1, "-", "1: odd rows end in half bricks so both wall ends are flush (length=12: 200 pieces); 0: odd rows are one brick shorter and the long rows' end bricks overhang half a brick, held by the rows above (length=13: 200 bricks)"},
	};
}

std::unique_ptr<SceneContent> createWall(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int rows = build::countParam(params, "rows", 1);
	const int length = build::countParam(params, "length", 2);
	const btVector3 half = btScalar(0.5) * btVector3(build::positiveParam(params, "brickLength"), build::positiveParam(params, "brickHeight"), build::positiveParam(params, "brickDepth"));
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	const btScalar gap = build::nonNegativeParam(params, "gap");
	const btScalar pitch = 2 * half.x() + gap;  // m, centre distance of neighbours in a row
	const bool halfBricks = build::nonNegativeParam(params, "halfBricks") > 0;

	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, btScalar(length) * pitch + 2 * half.y() * btScalar(rows), mu);
	btCollisionShape* shape = content->addShape(new btBoxShape(half));
	// A half brick fills the half pitch at each end of a short row, less one gap.
	const btScalar halfLength = pitch / 2 - gap;  // m
	btCollisionShape* halfShape = content->addShape(new btBoxShape(btVector3(halfLength / 2, half.y(), half.z())));
	for (int row = 0; row < rows; ++row)
	{
		const int count = (row % 2 == 0) ? length : length - 1;
		const btScalar firstX = -btScalar(count - 1) * pitch / 2;  // rows are centred: odd rows shift by half a brick
		const btScalar y = build::columnCentreY(0, half.y(), row);
		for (int i = 0; i < count; ++i)
		{
			btRigidBody* brick = content->addBody(shape, mass, build::at(firstX + btScalar(i) * pitch, y, 0), mu);
			if (i == count / 2 && row == 0)
				content->name("bottom", brick);
			if (i == count / 2 && row == rows - 1)
				content->name("top", brick);
		}
		if (halfBricks && row % 2 == 1)
		{
			const btScalar endX = -btScalar(length - 1) * pitch / 2 - half.x() + halfLength / 2;  // flush with the long rows
			const btScalar halfMass = mass * halfLength / (2 * half.x());
			content->addBody(halfShape, halfMass, build::at(endX, y, 0), mu);
			content->addBody(halfShape, halfMass, build::at(-endX, y, 0), mu);
		}
	}
	build::finishScene(*content, true);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// round_tower: rings of bricks laid tangentially around the y axis, alternate rings turned by half a
// brick; 20 rings of 16 make 320 bricks.

Params roundTowerParams()
{
	return {
		{"ring", 16, "-", "bricks per ring"},
		{"rings", 20, "-", "number of rings"},
		{"brickLength", 0.6, "m", "brick extent along the ring (tangential)"},
		{"brickHeight", 0.2, "m", "brick extent along y"},
		{"brickDepth", 0.3, "m", "brick extent across the ring (radial)"},
		{"mass", 1, "kg", "mass of each brick"},
		{"mu", 0.6, "-", build::kMuDescription},
		{"gap", build::kSideGap, "m", "gap between the inner corners of neighbouring bricks"},
	};
}

std::unique_ptr<SceneContent> createRoundTower(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int ring = build::countParam(params, "ring", 3);
	const int rings = build::countParam(params, "rings", 1);
	const btVector3 half = btScalar(0.5) * btVector3(build::positiveParam(params, "brickLength"), build::positiveParam(params, "brickHeight"), build::positiveParam(params, "brickDepth"));
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	const btScalar gap = build::nonNegativeParam(params, "gap");

	// The inner faces form a regular polygon with `ring` sides of length brickLength + gap; its apothem
	// a = side / (2 tan(pi / ring)). Outside the inner faces neighbours only diverge.
	const btScalar step = SIMD_2_PI / btScalar(ring);  // rad between neighbouring bricks
	const btScalar innerApothem = (2 * half.x() + gap) / (2 * btTan(step / 2));
	const btScalar radius = innerApothem + half.z();  // m, of the brick centres

	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, 2 * (radius + 2 * half.y() * btScalar(rings)), mu);
	btCollisionShape* shape = content->addShape(new btBoxShape(half));
	const btVector3 up(0, 1, 0);
	for (int level = 0; level < rings; ++level)
	{
		const btScalar phase = (level % 2 == 0) ? 0 : step / 2;  // running bond
		const btScalar y = build::columnCentreY(0, half.y(), level);
		for (int i = 0; i < ring; ++i)
		{
			const btScalar angle = phase + btScalar(i) * step;  // of the brick centre, from +x towards +z
			// Turning by pi/2 - angle about y takes the brick's z (depth) to the radial direction.
			const btTransform xf = build::rotatedAt(up, SIMD_HALF_PI - angle, btVector3(radius * btCos(angle), y, radius * btSin(angle)));
			btRigidBody* brick = content->addBody(shape, mass, xf, mu);
			if (i == 0 && level == 0)
				content->name("bottom", brick);
			if (i == 0 && level == rings - 1)
				content->name("top", brick);
		}
	}
	content->facts["radius"] = radius;
	build::finishScene(*content, true);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// door: a lintel on two columns of equal height but unequal box counts ("goal post"); the right
// column's boxes are flatter so both tops are level.

Params doorParams()
{
	return {
		{"left", 2, "-", "boxes in the left column"},
		{"right", 4, "-", "boxes in the right column (each left * size / right high)"},
		{"span", 2.5, "m", "distance between the column centres"},
		{"size", 0.5, "m", "edge of the left column's cubes (and width and depth of the right column's boxes)"},
		{"mass", 1, "kg", "mass of each column box"},
		{"lintelLength", 3, "m", "lintel extent along x"},
		{"lintelHeight", 0.25, "m", "lintel extent along y"},
		{"lintelDepth", 0.5, "m", "lintel extent along z"},
		{"lintelMass", 2, "kg", "mass of the lintel"},
		{"mu", 0.6, "-", build::kMuDescription},
	};
}

std::unique_ptr<SceneContent> createDoor(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int left = build::countParam(params, "left", 1);
	const int right = build::countParam(params, "right", 1);
	const btScalar span = build::positiveParam(params, "span");
	const btScalar size = build::positiveParam(params, "size");
	const btScalar mass = build::positiveParam(params, "mass");
	const btVector3 lintelHalf = btScalar(0.5) * btVector3(build::positiveParam(params, "lintelLength"), build::positiveParam(params, "lintelHeight"), build::positiveParam(params, "lintelDepth"));
	const btScalar lintelMass = build::positiveParam(params, "lintelMass");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	build::require(span > size + btScalar(build::kSideGap), "span must keep the columns apart");
	build::require(lintelHalf.x() > span / 2, "lintelLength must reach past both column centres");

	const btScalar columnHeight = btScalar(left) * size;  // m, the same for both columns
	const btScalar leftHalfHeight = size / 2;
	const btScalar rightHalfHeight = columnHeight / (2 * btScalar(right));

	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, 2 * (span + columnHeight), mu);
	btCollisionShape* leftShape = content->addShape(new btBoxShape(btVector3(size / 2, leftHalfHeight, size / 2)));
	btCollisionShape* rightShape = content->addShape(new btBoxShape(btVector3(size / 2, rightHalfHeight, size / 2)));
	btRigidBody* leftTop = nullptr;
	btRigidBody* rightTop = nullptr;
	for (int level = 0; level < left; ++level)
		leftTop = content->addBody(leftShape, mass, build::at(-span / 2, build::columnCentreY(0, leftHalfHeight, level), 0), mu);
	for (int level = 0; level < right; ++level)
		rightTop = content->addBody(rightShape, mass, build::at(span / 2, build::columnCentreY(0, rightHalfHeight, level), 0), mu);

	// Each contact costs one rest overlap, so the column with more boxes ends a few overlaps lower:
	// rest the lintel on the lower top (it then sinks slightly deeper into the other one).
	const btScalar leftTopY = build::columnCentreY(0, leftHalfHeight, left - 1) + leftHalfHeight;
	const btScalar rightTopY = build::columnCentreY(0, rightHalfHeight, right - 1) + rightHalfHeight;
	const btScalar lintelY = build::columnCentreY(btMin(leftTopY, rightTopY), lintelHalf.y(), 0);
	btCollisionShape* lintelShape = content->addShape(new btBoxShape(lintelHalf));
	content->name("lintel", content->addBody(lintelShape, lintelMass, build::at(0, lintelY, 0), mu));
	content->name("leftTop", leftTop);
	content->name("rightTop", rightTop);
	build::finishScene(*content, true);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// arch: a semicircular arch of wedge voussoirs standing on the ground, optionally loaded by a column of
// boxes on the keystone. A hard case: it holds only through friction and compression across every joint.

Params archParams()
{
	return {
		{"blocks", 17, "-", "voussoirs (odd, so there is a keystone)"},
		{"radius", 2, "m", "inner radius"},
		{"thickness", 0.4, "m", "radial thickness of the voussoirs"},
		{"depth", 0.5, "m", "extent along z"},
		{"density", 2000, "kg/m^3", "density of voussoirs and load boxes"},
		{"mu", 0.6, "-", build::kMuDescription},
		{"load", 0, "-", "boxes stacked on the keystone"},
		{"loadSize", 0.2, "m", "edge of each load cube"},
	};
}

std::unique_ptr<SceneContent> createArch(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int blocks = build::countParam(params, "blocks", 3);
	const btScalar innerRadius = build::positiveParam(params, "radius");
	const btScalar thickness = build::positiveParam(params, "thickness");
	const btScalar halfDepth = build::positiveParam(params, "depth") / 2;
	const btScalar density = build::positiveParam(params, "density");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	const int load = build::countParam(params, "load", 0);
	const btScalar loadHalf = build::positiveParam(params, "loadSize") / 2;
	build::require(blocks % 2 == 1, "blocks must be odd so that a keystone sits at the crown");
	const btScalar outerRadius = innerRadius + thickness;
	const btScalar wedgeAngle = SIMD_PI / btScalar(blocks);  // rad per voussoir

	// All voussoirs are congruent: one hull, built in the keystone's position (centred on the +y axis)
	// around its own centroid, and turned about the arch centre for the others. The section is a
	// quadrilateral (inner and outer faces are chords), counter-clockwise.
	const btScalar a0 = SIMD_HALF_PI - wedgeAngle / 2, a1 = SIMD_HALF_PI + wedgeAngle / 2;
	const std::vector<btVector3> section = {
		btVector3(innerRadius * btCos(a0), innerRadius * btSin(a0), 0), btVector3(outerRadius * btCos(a0), outerRadius * btSin(a0), 0),
		btVector3(outerRadius * btCos(a1), outerRadius * btSin(a1), 0), btVector3(innerRadius * btCos(a1), innerRadius * btSin(a1), 0)};
	btScalar sectionArea;
	btVector3 centroid;
	polygonAreaCentroid(section, sectionArea, centroid);
	const btScalar blockMass = density * sectionArea * 2 * halfDepth;

	auto content = std::make_unique<SceneContent>(world);
	btRigidBody* ground = build::addGround(*content, 2 * outerRadius, mu);
	// Hull-box pairs use the exact polyhedral clipping path (no collision margin) only when both shapes
	// carry polyhedral features; otherwise GJK would inflate each voussoir by its 4 cm margin.
	static_cast<btBoxShape*>(ground->getCollisionShape())->initializePolyhedralFeatures();
	auto* wedge = new btConvexHullShape();
	for (const btVector3& corner : section)
	{
		wedge->addPoint(corner - centroid + btVector3(0, 0, -halfDepth), false);
		wedge->addPoint(corner - centroid + btVector3(0, 0, halfDepth), false);
	}
	wedge->recalcLocalAabb();
	wedge->initializePolyhedralFeatures();
	content->addShape(wedge);

	// The arch centre sinks one rest overlap, so both springing joints sit in the ground's top face.
	const btVector3 archCentre(0, -btScalar(build::kRestOverlap), 0);
	const btVector3 zAxis(0, 0, 1);
	for (int i = 0; i < blocks; ++i)
	{
		const btScalar turn = (btScalar(i) + btScalar(0.5)) * wedgeAngle - SIMD_HALF_PI;  // from the keystone position
		const btQuaternion rotation(zAxis, turn);
		const btTransform xf(rotation, archCentre + quatRotate(rotation, centroid));
		btRigidBody* block = content->addBody(wedge, blockMass, xf, mu);
		if (i == blocks / 2)
			content->name("keystone", block);
	}

	// Load cubes stand on the keystone's flat outer face.
	const btScalar keystoneTopY = archCentre.y() + outerRadius * btCos(wedgeAngle / 2);
	auto* loadShape = new btBoxShape(btVector3(loadHalf, loadHalf, loadHalf));
	loadShape->initializePolyhedralFeatures();
	content->addShape(loadShape);
	const btScalar loadMass = density * 8 * loadHalf * loadHalf * loadHalf;
	for (int level = 0; level < load; ++level)
		content->addBody(loadShape, loadMass, build::at(0, build::columnCentreY(keystoneTopY, loadHalf, level), 0), mu);

	content->facts["keystoneTopY"] = keystoneTopY;
	content->facts["blockMass"] = blockMass;
	build::finishScene(*content, true);
	return content;
}

// ---------------------------------------------------------------------------------------------------
// card_house: pairs of thin cards leaning against each other form tents; one flat card per level lies
// across all the level's tents and carries the next level. A hard case: thin bodies held by edge
// contacts and friction.
//
// Why one flat card per level: the partners of a tent meet edge to edge, and Bullet gives that contact
// the face normal of one of them. A load on the other card's ridge alone would have to cross the apex as
// pure friction, which no mu holds; a flat card that covers both ridge edges of every tent below loads
// each apex symmetrically, and then the apex only carries the horizontal thrust.

Params cardHouseParams()
{
	return {
		{"levels", 3, "-", "tents in the bottom level (and number of levels)"},
		{"mu", 0.7, "-", build::kMuDescription},
		{"leanDeg", 25, "deg", "angle of each leaning card from the vertical"},
		{"cardLength", 0.4, "m", "leaning card extent along its slope"},
		{"cardThickness", 0.004, "m", "card thickness"},
		{"cardDepth", 0.4, "m", "card extent along z"},
		{"cardMass", 0.01, "kg", "mass of each card"},
	};
}

std::unique_ptr<SceneContent> createCardHouse(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int levels = build::countParam(params, "levels", 1);
	const btScalar mu = build::nonNegativeParam(params, "mu");
	const btScalar lean = build::degreesToRadians(build::positiveParam(params, "leanDeg"));
	const btScalar length = build::positiveParam(params, "cardLength");
	const btScalar thickness = build::positiveParam(params, "cardThickness");
	const btScalar halfDepth = build::positiveParam(params, "cardDepth") / 2;
	const btScalar mass = build::positiveParam(params, "cardMass");
	build::require(lean < SIMD_HALF_PI, "leanDeg must be below 90");
	const btScalar s = btSin(lean), c = btCos(lean);
	const btScalar overlap = btScalar(build::kRestOverlap);

	// Geometry of a tent relative to its apex line x = tentX (where the two inner top edges meet):
	const btScalar centreDx = thickness / 2 * c + length / 2 * s;   // m, apex to a card centre
	const btScalar halfRise = thickness / 2 * s + length / 2 * c;   // m, card centre to its lowest / highest edge
	const btScalar footDx = length * s + thickness * c;             // m, apex to the outer foot edge
	const btScalar ridgeDx = thickness * c;                         // m, apex to the outer top edges (they carry the flat cards)
	const btScalar tentClearance = btScalar(0.02);                  // m, between the feet of neighbouring tents
	const btScalar tentPitch = 2 * footDx + tentClearance;          // m
	const btScalar flatOverhang = btScalar(0.02);                   // m, of a flat card past the outermost ridge edges

	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, 2 * btScalar(levels) * tentPitch, mu);
	btCollisionShape* leaningShape = content->addShape(new btBoxShape(btVector3(thickness / 2, length / 2, halfDepth)));
	const btVector3 zAxis(0, 0, 1);
	btScalar baseY = 0;  // m, top of what the current level stands on
	btRigidBody* top = nullptr;
	for (int level = 0; level < levels; ++level)
	{
		const int tents = levels - level;
		const btScalar firstTentX = -btScalar(tents - 1) * tentPitch / 2;
		const btScalar cardY = baseY + halfRise - overlap;
		for (int t = 0; t < tents; ++t)
		{
			const btScalar apexX = firstTentX + btScalar(t) * tentPitch;
			// The partners overlap by one rest overlap where their inner top edges meet.
			top = content->addBody(leaningShape, mass, build::rotatedAt(zAxis, -lean, btVector3(apexX - centreDx + overlap / 2, cardY, 0)), mu);
			content->addBody(leaningShape, mass, build::rotatedAt(zAxis, lean, btVector3(apexX + centreDx - overlap / 2, cardY, 0)), mu);
		}
		if (tents == 1)
			break;  // the top tent carries nothing
		const btScalar ridgeY = cardY + halfRise;
		const btScalar flatY = build::columnCentreY(ridgeY, thickness / 2, 0);
		const btScalar flatHalfLength = btScalar(tents - 1) * tentPitch / 2 + ridgeDx + flatOverhang;
		btCollisionShape* flatShape = content->addShape(new btBoxShape(btVector3(flatHalfLength, thickness / 2, halfDepth)));
		content->addBody(flatShape, mass, build::at(0, flatY, 0), mu);
		baseY = flatY + thickness / 2;
	}
	content->name("top", top);
	content->facts["cards"] = double(content->dynamicBodies().size());
	build::finishScene(*content, true);
	return content;
}

}  // namespace scenes
