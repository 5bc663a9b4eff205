// The shapes and grounds of the shape grid (issue 37): every scene that takes a "shape" or a
// "ground" parameter builds its bodies and its ground here, so one number picks the same body
// or ground in every scene.
//
// Shapes (a body fitting half extents h, its bottom face or lowest point at -h.y):
//   0 btBoxShape(h)
//   1 btConvexHullShape of the box's 8 corners moved in by the margin (GJK/EPA, one new point per step)
//   2 the box's 8 corners at h, margin 0, with initializePolyhedralFeatures (Bullet's polyhedral
//     clipping of the bare faces, a full patch)
//   3 hexagonal prism, btConvexHullShape, circumradius h.x, half height h.y (margin included)
//   4 btCylinderShape(h): radius h.x, axis y
//   5 btCompoundShape of two boxes (h.x / 2, h.y, h.z) side by side: a body made of parts
//   6 btCapsuleShapeX lying along x: radius h.y, overall length 2 h.x
//   7 btSphereShape of radius h.y
// Grounds (top surface at y = 0, static, friction set by the caller):
//   0 btBoxShape slab (the registry's standard ground)
//   1 btStaticPlaneShape
//   2 btBvhTriangleMeshShape: a flat grid of square cells, two triangles each
//   3 the same grid with Bullet's internal-edge adjustment (btGenerateInternalEdgeInfo, and
//     btAdjustInternalEdgeContacts from gContactAddedCallback)
//   4 btHeightfieldTerrainShape, flat, the same cells
// The grid's lines are offset a quarter cell from the origin, so a body centred on x = 0 or
// z = 0 rests across internal edges but not with a corner on one.

#include "SceneBuild.h"

#include <BulletCollision/CollisionDispatch/btInternalEdgeUtility.h>
#include <BulletCollision/CollisionShapes/btHeightfieldTerrainShape.h>
#include <BulletCollision/CollisionShapes/btTriangleInfoMap.h>

#include <string>
#include <vector>

namespace scenes
{
namespace build
{
namespace
{
constexpr btScalar kCell = btScalar(1);  // m, side of a mesh or heightfield cell

/// Bullet's internal-edge fix, for every contact a body makes with a mesh ground of kind 3 (the
/// ground carries CF_CUSTOM_MATERIAL_CALLBACK, so no other pair calls this).
bool adjustInternalEdges(btManifoldPoint& cp, const btCollisionObjectWrapper* w0, int partId0, int index0,
						 const btCollisionObjectWrapper* w1, int partId1, int index1)
{
	if (w1->getCollisionShape()->getShapeType() == TRIANGLE_SHAPE_PROXYTYPE)
		btAdjustInternalEdgeContacts(cp, w1, w0, partId1, index1);
	else if (w0->getCollisionShape()->getShapeType() == TRIANGLE_SHAPE_PROXYTYPE)
		btAdjustInternalEdgeContacts(cp, w0, w1, partId0, index0);
	return true;
}

btCollisionShape* boxHull(const btVector3& h, bool features)
{
	btConvexHullShape* hull = new btConvexHullShape();
	// GJK rounds the points out by the margin, so they sit a margin inside h. Bullet's polyhedral
	// clipping (features, both bodies) uses the bare faces while GJK against the ground still adds
	// the margin, so the features hull gets margin 0 and its points at h: one surface for both.
	if (features) hull->setMargin(0);
	const btVector3 p = h - btVector3(1, 1, 1) * hull->getMargin();
	for (int i = 0; i < 8; ++i)
		hull->addPoint(btVector3((i & 1) ? p.x() : -p.x(), (i & 2) ? p.y() : -p.y(), (i & 4) ? p.z() : -p.z()), false);
	hull->recalcLocalAabb();
	if (features)
		hull->initializePolyhedralFeatures();
	return hull;
}

btCollisionShape* hexagonalPrism(const btVector3& h)
{
	btConvexHullShape* hull = new btConvexHullShape();
	const btScalar r = h.x() - hull->getMargin(), y = h.y() - hull->getMargin();  // rounded out by the margin
	for (int k = 0; k < 6; ++k)
	{
		const btScalar a = btScalar(k) * SIMD_PI / 3;
		for (int s = -1; s <= 1; s += 2)
			hull->addPoint(btVector3(r * btCos(a), btScalar(s) * y, r * btSin(a)), false);
	}
	hull->recalcLocalAabb();
	return hull;
}

/// (cells + 1)^2 grid vertices over [-half, half]^2 at y = 0, shifted by a quarter cell.
int gridCells(btScalar halfWidth) { return btMax(2, int(2 * halfWidth / kCell)); }
}  // namespace

const char* shapeKindNames() { return "0 box, 1 hull, 2 hull+features, 3 hexagonal prism, 4 cylinder, 5 compound, 6 capsule, 7 sphere"; }
const char* groundKindNames() { return "0 box, 1 plane, 2 triangle mesh, 3 mesh+internal edges, 4 heightfield"; }

btCollisionShape* addShapeOf(SceneContent& content, int kind, const btVector3& h)
{
	switch (kind)
	{
		case kBox:
			return content.addShape(new btBoxShape(h));
		case kHull:
		case kHullFeatures:
			return content.addShape(boxHull(h, kind == kHullFeatures));
		case kHexPrism:
			return content.addShape(hexagonalPrism(h));
		case kCylinder:
			return content.addShape(new btCylinderShape(h));
		case kCompound:
		{
			const btVector3 part(h.x() / 2, h.y(), h.z());
			btCollisionShape* child = content.addShape(new btBoxShape(part));
			btCompoundShape* compound = new btCompoundShape();
			compound->addChildShape(at(-part.x(), 0, 0), child);
			compound->addChildShape(at(part.x(), 0, 0), child);
			return content.addShape(compound);
		}
		case kCapsule:
			require(h.x() > h.y(), "a capsule needs half width > half height (its radius)");
			return content.addShape(new btCapsuleShapeX(h.y(), 2 * (h.x() - h.y())));
		case kSphere:
			return content.addShape(new btSphereShape(h.y()));
		default:
			require(false, std::string("shape must be one of: ") + shapeKindNames());
			return nullptr;
	}
}

btRigidBody* addGroundOf(SceneContent& content, int kind, btScalar footprintHalfWidth, btScalar mu)
{
	if (kind == kBoxGround)
		return addGround(content, footprintHalfWidth, mu);
	const btScalar halfWidth = btMax(btScalar(kMinGroundHalfWidth) / 2, footprintHalfWidth);
	btCollisionShape* shape = nullptr;
	btTransform xf = at(0, 0, 0);
	if (kind == kPlaneGround)
	{
		shape = content.addShape(new btStaticPlaneShape(btVector3(0, 1, 0), 0));
	}
	else if (kind == kMeshGround || kind == kMeshEdgesGround)
	{
		const int cells = gridCells(halfWidth);
		const btScalar origin = -btScalar(cells) * kCell / 2 + kCell / 4;
		btTriangleMesh* mesh = content.keep(new btTriangleMesh());
		auto vertex = [&](int i, int k) { return btVector3(origin + btScalar(i) * kCell, 0, origin + btScalar(k) * kCell); };
		for (int i = 0; i < cells; ++i)
			for (int k = 0; k < cells; ++k)
			{
				// Counter-clockwise seen from above: the faces' normals point up.
				mesh->addTriangle(vertex(i, k), vertex(i, k + 1), vertex(i + 1, k + 1));
				mesh->addTriangle(vertex(i, k), vertex(i + 1, k + 1), vertex(i + 1, k));
			}
		btBvhTriangleMeshShape* meshShape = new btBvhTriangleMeshShape(mesh, true);
		shape = content.addShape(meshShape);
		if (kind == kMeshEdgesGround)
			btGenerateInternalEdgeInfo(meshShape, content.keep(new btTriangleInfoMap()));
	}
	else if (kind == kHeightfieldGround)
	{
		const int cells = gridCells(halfWidth);
		std::vector<btScalar>* heights = content.keep(new std::vector<btScalar>(size_t(cells + 1) * size_t(cells + 1), btScalar(0)));
		// Samples at 0 between bounds -1 and 1: Bullet centres the shape on its bounds, so its
		// surface is at the body's origin. The samples are btScalar: this (legacy) constructor
		// takes PHY_FLOAT to mean btScalar, so float samples read as garbage in a double build.
		btHeightfieldTerrainShape* field = new btHeightfieldTerrainShape(cells + 1, cells + 1, heights->data(), 1, -1, 1, 1, PHY_FLOAT, false);
		field->setLocalScaling(btVector3(kCell, 1, kCell));
		shape = content.addShape(field);
		xf = at(kCell / 4, 0, kCell / 4);
	}
	else
	{
		require(false, std::string("ground must be one of: ") + groundKindNames());
	}
	btRigidBody* ground = content.addBody(shape, 0, xf, mu);
	if (kind == kMeshEdgesGround)
	{
		ground->setCollisionFlags(ground->getCollisionFlags() | btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK);
		gContactAddedCallback = adjustInternalEdges;  // called only for pairs with a flagged body
	}
	content.name("ground", ground);
	return ground;
}

}  // namespace build
}  // namespace scenes
