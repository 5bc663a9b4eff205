/*
BulletShockPropagation - velocity-based shock propagation for Bullet
Copyright (c) 2026 the BulletShockPropagation authors

This software is provided 'as-is', without any express or implied warranty.
In no event will the authors be held liable for any damages arising from the use of this software.
Permission is granted to anyone to use this software for any purpose,
including commercial applications, and to alter it and redistribute it freely,
subject to the following restrictions:
1. The origin of this software must not be misrepresented; you must not claim that you wrote the original software. If you use this software in a product, an acknowledgment in the product documentation would be appreciated but is not required.
2. Altered source versions must be plainly marked as such, and must not be misrepresented as being the original software.
3. This notice may not be removed or altered from any source distribution.
*/

#include "btContactPatch.h"

#include "BulletShockPropagation/btShockPropagationSettings.h"

#include "BulletCollision/CollisionDispatch/btCollisionObject.h"
#include "BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h"
#include "BulletCollision/CollisionDispatch/btManifoldResult.h"
#include "BulletCollision/CollisionShapes/btCompoundShape.h"
#include "BulletCollision/CollisionShapes/btConcaveShape.h"
#include "BulletCollision/CollisionShapes/btTriangleCallback.h"
#include "BulletCollision/CollisionShapes/btConvexShape.h"
#include "BulletCollision/CollisionShapes/btPolyhedralConvexShape.h"
#include "BulletCollision/CollisionShapes/btStaticPlaneShape.h"
#include "BulletCollision/NarrowPhaseCollision/btPersistentManifold.h"

namespace
{
const int kRim = 8;                          // support directions around the normal
const btScalar kSpread = btScalar(0.5);      // tangent of the directions' tilt from the normal (27 deg)

/// One side of the pair: its rim in world space (a face's corners or points of its edge), or a
/// flat ground that has no rim and is under every point.
struct PatchSide
{
	bool convex = false;
	bool flat = false;
	btVector3 planeNormal = btVector3(0, 0, 0);  // a flat side's normal (world)
	const btConcaveShape* concave = 0;  // a static mesh or heightfield: its triangles are looked up
	btTransform frame = btTransform::getIdentity();  // the side's world frame
	btVector3 rim[kRim];
	btScalar rimU[kRim], rimV[kRim];  // the rim in the tangent plane's coordinates
	int rimCount = 0;                 // distinct rim points (in order around the normal)
	bool flatRim = false;             // the rim points lie in one plane across the normal: a face
	btVector3 rimNormal = btVector3(0, 0, 0);  // the rim polygon's unit normal (Newell's), either way round
	btScalar rimTwiceArea = 0;        // the rim polygon's signed area in (u, v), doubled (m^2)
};

/// The shape a manifold of `object` touches and its world frame: the body's shape, or for a
/// btCompoundShape the child `childIndex` (Bullet's compound algorithms keep one manifold per child
/// pair and mark its points with the child's index).
bool partOf(const btCollisionObject* object, int childIndex, const btCollisionShape*& shape, btTransform& frame)
{
	shape = object->getCollisionShape();
	frame = object->getWorldTransform();
	if (shape->getShapeType() != COMPOUND_SHAPE_PROXYTYPE) return true;
	const btCompoundShape* compound = static_cast<const btCompoundShape*>(shape);
	if (childIndex < 0 || childIndex >= compound->getNumChildShapes()) return false;
	frame = frame * compound->getChildTransform(childIndex);
	shape = compound->getChildShape(childIndex);
	return true;
}

bool describeSide(const btCollisionShape* shape, const btTransform& frame, const btVector3& facing, const btVector3& t1, const btVector3& t2, btScalar flatness, PatchSide& side)
{
	if (shape->getShapeType() == STATIC_PLANE_PROXYTYPE)
	{
		side.flat = true;
		side.planeNormal = frame.getBasis() * static_cast<const btStaticPlaneShape*>(shape)->getPlaneNormal();
		return true;
	}
	side.frame = frame;
	if (shape->isConcave())
	{
		side.concave = static_cast<const btConcaveShape*>(shape);
		return true;
	}
	if (!shape->isConvex()) return false;
	side.convex = true;
	const btConvexShape* convex = static_cast<const btConvexShape*>(shape);
	btScalar margin = convex->getMargin();
	if (convex->isPolyhedral() && static_cast<const btPolyhedralConvexShape*>(convex)->getConvexPolyhedron()) margin = 0;
	for (int k = 0; k < kRim; ++k)
	{
		const btScalar angle = btScalar(k) * SIMD_PI / btScalar(4);
		const btVector3 direction = facing + kSpread * (btCos(angle) * t1 + btSin(angle) * t2);
		const btVector3 local = convex->localGetSupportingVertexWithoutMargin(direction * frame.getBasis());
		const btVector3 point = frame * local + facing * margin;
		if (!(point.length2() < BT_LARGE_FLOAT)) return false;
		const btScalar u = point.dot(t1), v = point.dot(t2);
		if (side.rimCount > 0)
		{
			const int last = side.rimCount - 1;
			if (btFabs(u - side.rimU[last]) + btFabs(v - side.rimV[last]) < SIMD_EPSILON * (btScalar(1) + btFabs(u) + btFabs(v))) continue;
		}
		side.rim[side.rimCount] = point;
		side.rimU[side.rimCount] = u;
		side.rimV[side.rimCount] = v;
		++side.rimCount;
	}
	// A face only if the rim is flat: a body touching with a corner or an edge has rim points at
	// different heights along the normal (its support in the tilted directions leaves the face).
	if (side.rimCount >= 3)
	{
		btVector3 normal(0, 0, 0);  // Newell's: the rim polygon's own normal
		for (int k = 0; k < side.rimCount; ++k)
		{
			const int next = (k + 1) % side.rimCount;
			normal += side.rim[k].cross(side.rim[next]);
			side.rimTwiceArea += side.rimU[k] * side.rimV[next] - side.rimU[next] * side.rimV[k];
		}
		const btScalar length = normal.length();
		if (length > SIMD_EPSILON)
		{
			side.rimNormal = normal / length;
			btScalar low = BT_LARGE_FLOAT, high = -BT_LARGE_FLOAT;
			for (int k = 0; k < side.rimCount; ++k)
			{
				low = btMin(low, (side.rim[k] - side.rim[0]).dot(side.rimNormal));
				high = btMax(high, (side.rim[k] - side.rim[0]).dot(side.rimNormal));
			}
			side.flatRim = high - low <= flatness;
		}
	}
	return true;
}

/// The triangle of a mesh or heightfield side under a world point: of the triangles within `range`
/// whose normal lies within faceAlignment of `along` and under which the point lies (its
/// projection inside, within `slack`), the nearest. Gives its normal (world, along `along`) and the
/// point's distance above its plane.
struct btTriangleUnder : public btTriangleCallback
{
	btVector3 m_point, m_along;  // in the shape's frame
	btScalar m_slack = 0;
	bool m_found = false;
	btScalar m_distance = 0;
	btVector3 m_normal;
	virtual void processTriangle(btVector3* t, int /*partId*/, int /*triangleIndex*/)
	{
		btVector3 normal = (t[1] - t[0]).cross(t[2] - t[0]);
		const btScalar length = normal.length();
		if (!(length > SIMD_EPSILON)) return;  // a degenerate triangle has no face
		normal /= length;
		if (normal.dot(m_along) < 0) normal = -normal;
		if (normal.dot(m_along) < btShockPropagationNumerics::faceAlignment()) return;
		const btScalar distance = (m_point - t[0]).dot(normal);
		for (int e = 0; e < 3; ++e)
		{
			const btVector3 edge = t[(e + 1) % 3] - t[e];
			const btVector3 inward = normal.cross(edge).normalized();
			if ((m_point - t[e]).dot(inward) < -m_slack) return;
		}
		if (!m_found || btFabs(distance) < btFabs(m_distance))
		{
			m_found = true;
			m_distance = distance;
			m_normal = normal;
		}
	}
};

bool triangleUnder(const PatchSide& side, const btVector3& point, const btVector3& along, btScalar range, btScalar slack,
				   btVector3& normal, btScalar& distance)
{
	btTriangleUnder query;
	query.m_point = side.frame.invXform(point);
	query.m_along = along * side.frame.getBasis();
	query.m_slack = slack;
	const btVector3 extent(range, range, range);
	side.concave->processAllTriangles(&query, query.m_point - extent, query.m_point + extent);
	if (!query.m_found) return false;
	normal = side.frame.getBasis() * query.m_normal;
	distance = query.m_distance;
	return true;
}

/// The point of segment [a, b] nearest to p.
btVector3 closestOnSegment(const btVector3& p, const btVector3& a, const btVector3& b)
{
	const btVector3 ab = b - a;
	const btScalar length2 = ab.length2();
	if (!(length2 > btScalar(0))) return a;
	return a + ab * btMax(btScalar(0), btMin(btScalar(1), (p - a).dot(ab) / length2));
}

/// Area of the convex hull of four points (u, v) of the tangent plane (m^2): the largest of the
/// three quadrilaterals through them and the four triangles (one point inside the others').
btScalar hullArea4(const btScalar* u, const btScalar* v)
{
	auto twice = [&](int a, int b, int c) { return btFabs((u[b] - u[a]) * (v[c] - v[a]) - (u[c] - u[a]) * (v[b] - v[a])); };
	auto quad = [&](int a, int b, int c, int d) {
		return btFabs(u[a] * v[b] - u[b] * v[a] + u[b] * v[c] - u[c] * v[b] + u[c] * v[d] - u[d] * v[c] + u[d] * v[a] - u[a] * v[d]);
	};
	btScalar best = btMax(btMax(quad(0, 1, 2, 3), quad(0, 1, 3, 2)), quad(0, 2, 1, 3));
	best = btMax(best, btMax(btMax(twice(0, 1, 2), twice(0, 1, 3)), btMax(twice(0, 2, 3), twice(1, 2, 3))));
	return best / 2;
}

/// The unit normal of the side's face turned along `along`: a flat ground's plane, a flat rim's
/// polygon; zero if the rim is not a face (a point, a line, a corner).
btVector3 faceNormal(const PatchSide& side, const btVector3& along)
{
	const btVector3 normal = side.flat ? side.planeNormal : (side.convex && side.flatRim ? side.rimNormal : btVector3(0, 0, 0));
	return normal.dot(along) < 0 ? -normal : normal;
}

/// Gives the point `normal` (from B into A) and `distance`, keeping its place on one body and moving
/// it along the normal on the other (B's point if `moveB`): the moved point lies on the reference
/// face's plane, the kept one stays on its own body's surface.
void placeAlong(btManifoldPoint& p, const btVector3& normal, btScalar distance, bool moveB, const btCollisionObject* objectA,
				const btCollisionObject* objectB)
{
	p.m_normalWorldOnB = normal;
	p.m_distance1 = distance;
	if (moveB)
	{
		p.m_positionWorldOnB = p.getPositionWorldOnA() - normal * distance;
		p.m_localPointB = objectB->getWorldTransform().invXform(p.m_positionWorldOnB);
	}
	else
	{
		p.m_positionWorldOnA = p.getPositionWorldOnB() + normal * distance;
		p.m_localPointA = objectA->getWorldTransform().invXform(p.m_positionWorldOnA);
	}
}

/// Whether (u, v) lies inside the side's rim polygon (ordered around n), within `slack` (m).
bool over(const PatchSide& side, btScalar u, btScalar v, btScalar slack)
{
	if (side.flat) return true;
	if (side.rimCount < 3 || !side.flatRim) return false;  // a point, a line or a corner: no face to rest on
	// The polygon's orientation from its area, so the test holds either way round.
	if (!(btFabs(side.rimTwiceArea) > slack * slack)) return false;
	const btScalar orientation = side.rimTwiceArea > 0 ? btScalar(1) : btScalar(-1);
	for (int i = 0; i < side.rimCount; ++i)
	{
		const int j = (i + 1) % side.rimCount;
		const btScalar eu = side.rimU[j] - side.rimU[i], ev = side.rimV[j] - side.rimV[i];
		const btScalar length = btSqrt(eu * eu + ev * ev);
		if (length <= btScalar(0)) continue;
		const btScalar cross = (eu * (v - side.rimV[i]) - ev * (u - side.rimU[i])) * orientation / length;
		if (cross < -slack) return false;
	}
	return true;
}

/// The segment through `count` points, if they lie on one (within `slack`): its ends, the two
/// points farthest apart (one point: both the same).
bool segmentThrough(const btVector3* points, int count, btScalar slack, btVector3& a, btVector3& b)
{
	if (count == 0) return false;
	a = b = points[0];
	btScalar longest = 0;
	for (int i = 0; i < count; ++i)
		for (int j = i + 1; j < count; ++j)
		{
			const btScalar length2 = (points[i] - points[j]).length2();
			if (length2 > longest)
			{
				longest = length2;
				a = points[i];
				b = points[j];
			}
		}
	for (int k = 0; k < count; ++k)
		if ((points[k] - closestOnSegment(points[k], a, b)).length2() > slack * slack) return false;
	return true;
}

/// Where a side that is no face touches (a sphere, a capsule on its side, a box's edge or corner):
/// its rim points nearest the other part along `facing` (within `reach` of the nearest), if they lie on one
/// segment parallel to the tangent plane. A rim edge that rises out of reach touches up to there
/// (a tilted capsule along its line, not at its lower end only), if that stays one segment (a
/// corner's edges leave it in several directions: the corner). Gives the segment's ends (one
/// point: both the same) and the nearest rim point's level along -facing.
bool touchingSegment(const PatchSide& side, const btVector3& facing, btScalar reach, btScalar slack, btVector3& a, btVector3& b, btScalar& nearest)
{
	if (!side.convex || side.flatRim || side.rimCount < 1) return false;
	nearest = BT_LARGE_FLOAT;
	for (int k = 0; k < side.rimCount; ++k) nearest = btMin(nearest, -side.rim[k].dot(facing));
	btVector3 touching[2 * kRim];
	int count = 0;
	for (int k = 0; k < side.rimCount; ++k)
		if (-side.rim[k].dot(facing) <= nearest + reach) touching[count++] = side.rim[k];
	const int within = count;
	for (int k = 0; k < side.rimCount; ++k)
	{
		const int next = (k + 1) % side.rimCount;
		const btScalar height = -side.rim[k].dot(facing) - nearest, nextHeight = -side.rim[next].dot(facing) - nearest;
		if ((height <= reach) != (nextHeight <= reach))
			touching[count++] = side.rim[k] + (side.rim[next] - side.rim[k]) * ((reach - height) / (nextHeight - height));
	}
	return segmentThrough(touching, count, slack, a, b) || segmentThrough(touching, within, slack, a, b);
}

/// Moves a point's position on one body (A's if `onA`) to `position`, its local point with it.
void moveOnBody(btManifoldPoint& p, bool onA, const btVector3& position, const btCollisionObject* object)
{
	(onA ? p.m_positionWorldOnA : p.m_positionWorldOnB) = position;
	(onA ? p.m_localPointA : p.m_localPointB) = object->getWorldTransform().invXform(position);
}
}  // namespace

btManifoldPoint btAddedContactPoint(const btManifoldPoint& reference, const btCollisionObject* objectA, const btCollisionObject* objectB,
									const btVector3& onA, const btVector3& onB, btScalar distance, const btVector3& normal)
{
	btManifoldPoint point = reference;  // the pair's combined coefficients, flags and frames
	point.m_normalWorldOnB = normal;
	point.m_localPointA = objectA->getWorldTransform().invXform(onA);
	point.m_localPointB = objectB->getWorldTransform().invXform(onB);
	point.m_positionWorldOnA = onA;
	point.m_positionWorldOnB = onB;
	point.m_distance1 = distance;
	point.m_lifeTime = 0;
	point.m_userPersistentData = 0;
	point.m_appliedImpulse = 0;
	point.m_prevRHS = 0;
	point.m_appliedImpulseLateral1 = 0;
	point.m_appliedImpulseLateral2 = 0;
	point.m_contactPointFlags &= ~BT_CONTACT_FLAG_LATERAL_FRICTION_INITIALIZED;
	if (gContactAddedCallback && ((objectA->getCollisionFlags() | objectB->getCollisionFlags()) & btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK))
	{
		const btCollisionObjectWrapper wrapA(0, objectA->getCollisionShape(), objectA, objectA->getWorldTransform(), point.m_partId0, point.m_index0);
		const btCollisionObjectWrapper wrapB(0, objectB->getCollisionShape(), objectB, objectB->getWorldTransform(), point.m_partId1, point.m_index1);
		(*gContactAddedCallback)(point, &wrapA, point.m_partId0, point.m_index0, &wrapB, point.m_partId1, point.m_index1);
	}
	return point;
}

int btCompleteContactPatch(btPersistentManifold& manifold, btScalar reach, btScalar keepDepth)
{
	const int initial = manifold.getNumContacts();
	if (initial < 1 || !(reach > btScalar(0))) return 0;
	const btCollisionObject* objectA = manifold.getBody0();
	const btCollisionObject* objectB = manifold.getBody1();
	if (objectA->getCollisionShape()->getShapeType() == BOX_SHAPE_PROXYTYPE && objectB->getCollisionShape()->getShapeType() == BOX_SHAPE_PROXYTYPE) return 0;  // D30
	// The two parts in touch: one child pair for a compound (every point names the same children).
	const int childA = manifold.getContactPoint(0).m_index0, childB = manifold.getContactPoint(0).m_index1;
	const bool compoundA = objectA->getCollisionShape()->getShapeType() == COMPOUND_SHAPE_PROXYTYPE;
	const bool compoundB = objectB->getCollisionShape()->getShapeType() == COMPOUND_SHAPE_PROXYTYPE;
	for (int j = 1; j < initial; ++j)
		if ((compoundA && manifold.getContactPoint(j).m_index0 != childA) || (compoundB && manifold.getContactPoint(j).m_index1 != childB)) return 0;
	const btCollisionShape* shapeA;
	const btCollisionShape* shapeB;
	btTransform frameA, frameB;
	if (!partOf(objectA, childA, shapeA, frameA) || !partOf(objectB, childB, shapeB, frameB)) return 0;
	// A resting patch: no point deeper than the breaking threshold (a deep overlap is a collision
	// being resolved, and its normal is EPA's way out, not a face's).
	const btScalar breaking = manifold.getContactBreakingThreshold();
	for (int j = 0; j < initial; ++j)
		if (!(manifold.getContactPoint(j).getDistance() >= -breaking)) return 0;
	const btScalar flatness = btScalar(1e-3) * breaking;  // m, how far a face's rim may leave its plane
	btVector3 n = manifold.getContactPoint(0).m_normalWorldOnB;  // from B into A
	if (!(btFabs(n.length2() - btScalar(1)) < btScalar(1e-3))) return 0;
	btVector3 t1, t2;
	btPlaneSpace1(n, t1, t2);
	PatchSide sides[2];
	if (!describeSide(shapeA, frameA, -n, t1, t2, flatness, sides[0]) || !describeSide(shapeB, frameB, n, t1, t2, flatness, sides[1])) return 0;
	if (!sides[0].convex && !sides[1].convex) return 0;
	// A face resting on a face: every point takes the reference face's normal, and its distance
	// along it. GJK/EPA's normal is the shapes' closest direction found to its tolerance: between a
	// cylinder and a 100 m ground box it was off by 2 mrad, and points of one patch with normals
	// that differ push the body sideways through their friction rows. The reference face: a
	// static part's (the ground does not tilt), else the larger one, as face clipping takes it.
	// Each point keeps its place on the other part and moves along the normal onto the reference
	// face's plane, so both stay on their part's surface (moving a sphere's point off its surface
	// instead flung bodies in hostile worlds, seeds 241 and 485: 89 and 603 m/s).
	const btVector3 faceA = faceNormal(sides[0], n), faceB = faceNormal(sides[1], n);
	int referenceSide = -1;  // the side whose face is imposed
	if (objectA->isStaticOrKinematicObject() && !faceA.isZero())
		referenceSide = 0;
	else if (objectB->isStaticOrKinematicObject() && !faceB.isZero())
		referenceSide = 1;
	else if (!faceA.isZero() && !faceB.isZero())
		referenceSide = btFabs(sides[0].rimTwiceArea) > btFabs(sides[1].rimTwiceArea) ? 0 : 1;
	else if (!faceA.isZero() || !faceB.isZero())
		referenceSide = faceA.isZero() ? 1 : 0;
	const btVector3 face = referenceSide == 0 ? faceA : (referenceSide == 1 ? faceB : btVector3(0, 0, 0));
	if (referenceSide >= 0 && face.dot(n) >= btShockPropagationNumerics::faceAlignment() && !(face == n))
	{
		n = face;
		for (int j = 0; j < initial; ++j)
		{
			btManifoldPoint& p = manifold.getContactPoint(j);
			placeAlong(p, n, (p.getPositionWorldOnA() - p.getPositionWorldOnB()).dot(n), referenceSide == 1, objectA, objectB);
		}
		btPlaneSpace1(n, t1, t2);
		sides[0] = PatchSide();
		sides[1] = PatchSide();
		describeSide(shapeA, frameA, -n, t1, t2, flatness, sides[0]);
		describeSide(shapeB, frameB, n, t1, t2, flatness, sides[1]);
	}
	const btScalar slack = btScalar(1e-3) * breaking;
	// A convex face resting on a mesh or heightfield: each point takes the normal of the triangle
	// under it, as Bullet's internal-edge adjustment would, where the convex face lies along it (a
	// point on an internal edge otherwise gets the edge's normal, and a sliding body catches on it).
	const int concaveSide = sides[0].concave ? 0 : (sides[1].concave ? 1 : -1);
	if (concaveSide >= 0)
	{
		const btVector3 convexFace = faceNormal(sides[1 - concaveSide], n);
		for (int j = 0; j < initial && !convexFace.isZero(); ++j)
		{
			btManifoldPoint& p = manifold.getContactPoint(j);
			const btVector3 onConvex = concaveSide == 1 ? p.getPositionWorldOnA() : p.getPositionWorldOnB();
			btVector3 normal;
			btScalar height;
			if (!triangleUnder(sides[concaveSide], onConvex, concaveSide == 1 ? n : -n, breaking, slack, normal, height)) continue;
			if (normal.dot(concaveSide == 1 ? convexFace : -convexFace) < btShockPropagationNumerics::faceAlignment()) continue;
			placeAlong(p, concaveSide == 1 ? normal : -normal, height, concaveSide == 1, objectA, objectB);
		}
	}
	// A part that is no face (a sphere, a capsule on its side, a box's edge or corner) touches a
	// face where its surface is nearest it: on its touching segment (a point for a sphere or a
	// corner). A point Bullet keeps from an earlier step is fixed in the part, and once a round
	// part rolls it lies beside that segment, where the normal force turns the part on (a capsule
	// on a box rolled like an inverted pendulum on its old point: the roll grew 2.2 times every
	// 20 steps). Each point goes back onto the segment, keeping its place along it, and takes its
	// distance to the face there; the segment's ends are the patch's rim (candidates below).
	btVector3 segment[2][2];
	bool touching[2] = {false, false};
	btScalar nearest[2] = {0, 0};  // each part's nearest rim point's level along its facing direction
	for (int s = 0; s < 2; ++s)
	{
		const PatchSide& other = sides[1 - s];
		touching[s] = (other.flat || other.concave || !faceNormal(other, n).isZero()) &&
					  touchingSegment(sides[s], s == 0 ? -n : n, breaking, slack, segment[s][0], segment[s][1], nearest[s]);
		for (int j = 0; j < initial && touching[s]; ++j)
		{
			btManifoldPoint& p = manifold.getContactPoint(j);
			const btVector3 onPart = s == 0 ? p.getPositionWorldOnA() : p.getPositionWorldOnB();
			// Only a point of the touching part, within reach of the nearest as the segment is: a
			// point higher up is where another part of the surface nears the face (a tilted
			// capsule's raised end, 12 mm up, moved 0.54 m onto its lower end and merged there
			// left the capsule one support), a contact of its own that stays where Bullet has it.
			if (-onPart.dot(s == 0 ? -n : n) > nearest[s] + breaking) continue;
			const btVector3 onSegment = closestOnSegment(onPart, segment[s][0], segment[s][1]);
			if (!((onSegment - onPart).length2() > btScalar(0))) continue;
			btVector3 normal = n;
			btScalar distance;
			if (other.concave)
			{
				if (!triangleUnder(other, onSegment, s == 0 ? n : -n, breaking, slack, normal, distance)) continue;
				if (s == 1) normal = -normal;
			}
			else
			{
				// Over the other part's face (inside its rim; a plane is under every point).
				if (!over(other, onSegment.dot(t1), onSegment.dot(t2), slack)) continue;
				distance = s == 0 ? (onSegment - p.getPositionWorldOnB()).dot(n) : (p.getPositionWorldOnA() - onSegment).dot(n);
			}
			if (!(distance >= -breaking && distance <= breaking)) continue;
			moveOnBody(p, s == 0, onSegment, s == 0 ? objectA : objectB);
			placeAlong(p, normal, distance, s == 0, objectA, objectB);
		}
	}
	// Points that went onto the same spot (a rolling ball's old points, all back at its one point)
	// are one contact: the later ones go (Bullet's removal: the app's callbacks run).
	if (touching[0] || touching[1])
		for (int j = manifold.getNumContacts() - 1; j > 0; --j)
			for (int i = 0; i < j; ++i)
				if ((manifold.getContactPoint(i).getPositionWorldOnA() - manifold.getContactPoint(j).getPositionWorldOnA()).length2() <= slack * slack)
				{
					manifold.removeContactPoint(j);
					break;
				}
	const btManifoldPoint reference = manifold.getContactPoint(0);

	// Candidates: rim points of either side within reach of the other's plane and over its face.
	// Each side's rim (or segment ends), then the crossings of the two rims' edges.
	const int kMaxCandidates = 2 * kRim + kRim * kRim;
	btVector3 candidateA[kMaxCandidates], candidateNormal[kMaxCandidates];
	btScalar candidateDistance[kMaxCandidates];
	int numCandidates = 0;
	for (int s = 0; s < 2; ++s)
	{
		const PatchSide& side = sides[s];
		const PatchSide& other = sides[1 - s];
		const btVector3 otherPoint = s == 0 ? reference.getPositionWorldOnB() : reference.getPositionWorldOnA();
		// A face's rim, or a touching segment's two ends (a capsule on its side; a sphere's or a
		// corner's one point is the contact Bullet has).
		const bool line = touching[s] && (segment[s][1] - segment[s][0]).length2() > slack * slack;
		const int count = side.flatRim ? side.rimCount : (line ? 2 : 0);
		for (int k = 0; k < count; ++k)
		{
			const btVector3 rim = side.flatRim ? side.rim[k] : segment[s][k];
			// Distance between the faces at this point, positive apart (A above B along n).
			btScalar distance;
			btVector3 normal = n;
			if (other.concave)
			{
				// The triangle under the rim point is the face it rests on (none: it is not over one).
				btScalar height;
				if (!triangleUnder(other, rim, s == 0 ? n : -n, breaking, slack, normal, height)) continue;
				if (s == 1) normal = -normal;
				distance = height;
			}
			else
			{
				// Along n to the other's face: the plane of its rim (or the ground plane) through
				// its point of the contact, which is the plane across n only where that face is
				// (a face tilted from n: dominoes leaning 11 degrees apart, one touching the other
				// with its top edge, read a corner 1 m down the face as 7.6 mm deep, 19 cm apart in
				// truth, and held each other up on such points).
				const btVector3 otherFace = faceNormal(other, n);
				const btScalar cosine = otherFace.dot(n);
				const btScalar apart = otherFace.isZero() || otherFace == n || !(cosine > btScalar(0)) ? (otherPoint - rim).dot(n)
																									  : (otherPoint - rim).dot(otherFace) / cosine;
				distance = s == 0 ? -apart : apart;
				if (!over(other, rim.dot(t1), rim.dot(t2), slack)) continue;
			}
			if (!(distance <= reach && distance >= -breaking)) continue;
			candidateA[numCandidates] = s == 0 ? rim : rim + normal * distance;
			candidateNormal[numCandidates] = normal;
			candidateDistance[numCandidates] = distance;
			++numCandidates;
		}
	}
	// Two faces crossing (planks of a crib, hulls whose faces overlap in part): the patch's corners
	// are also where an edge of one rim crosses an edge of the other (their polygons' intersection,
	// as face clipping finds it). Each crossing is a candidate on A's face, at the faces' distance.
	// Both faces across n (within the snap's alignment): their distance is then one number.
	const bool bothFaces = sides[0].flatRim && sides[1].flatRim && faceNormal(sides[0], n).dot(n) >= btShockPropagationNumerics::faceAlignment() &&
						   faceNormal(sides[1], n).dot(n) >= btShockPropagationNumerics::faceAlignment();
	const btScalar heightA = bothFaces ? sides[0].rim[0].dot(n) : btScalar(0);
	const btScalar faceDistance = bothFaces ? heightA - sides[1].rim[0].dot(n) : BT_LARGE_FLOAT;
	if (faceDistance <= reach && faceDistance >= -breaking)
	{
		const btScalar distance = faceDistance;
		for (int i = 0; i < sides[0].rimCount; ++i)
		{
			const int i1 = (i + 1) % sides[0].rimCount;
			const btScalar au = sides[0].rimU[i], av = sides[0].rimV[i];
			const btScalar eu = sides[0].rimU[i1] - au, ev = sides[0].rimV[i1] - av;
			for (int j = 0; j < sides[1].rimCount && numCandidates < kMaxCandidates; ++j)
			{
				const int j1 = (j + 1) % sides[1].rimCount;
				const btScalar bu = sides[1].rimU[j], bv = sides[1].rimV[j];
				const btScalar fu = sides[1].rimU[j1] - bu, fv = sides[1].rimV[j1] - bv;
				// a + s e = b + t f, s and t in [0, 1].
				const btScalar det = eu * fv - ev * fu;
				if (!(btFabs(det) > SIMD_EPSILON * (eu * eu + ev * ev + fu * fu + fv * fv))) continue;  // parallel edges
				const btScalar along = ((bu - au) * fv - (bv - av) * fu) / det;
				const btScalar across = ((bu - au) * ev - (bv - av) * eu) / det;
				if (!(along >= 0 && along <= 1 && across >= 0 && across <= 1)) continue;
				const btScalar u = au + along * eu, v = av + along * ev;
				candidateA[numCandidates] = t1 * u + t2 * v + n * heightA;
				candidateNormal[numCandidates] = n;
				candidateDistance[numCandidates] = distance;
				++numCandidates;
			}
		}
	}
	// A new point at candidate c: the pair's combined coefficients, flags and frames from the
	// manifold's first point, the app's callback run where a body asks for it.
	auto makePoint = [&](int c) {
		return btAddedContactPoint(reference, objectA, objectB, candidateA[c], candidateA[c] - candidateNormal[c] * candidateDistance[c],
								   candidateDistance[c], candidateNormal[c]);
	};
	const btScalar sameSpot2 = breaking * breaking;
	auto gapToPoints = [&](int c) {
		btScalar gap = BT_LARGE_FLOAT;
		for (int j = 0; j < manifold.getNumContacts(); ++j) gap = btMin(gap, (manifold.getContactPoint(j).getPositionWorldOnA() - candidateA[c]).length2());
		return gap;
	};

	// Fill, farthest first: each added point is the candidate farthest from every point there.
	int added = 0;
	while (manifold.getNumContacts() < MANIFOLD_CACHE_SIZE)
	{
		int best = -1;
		btScalar bestGap = sameSpot2;
		for (int c = 0; c < numCandidates; ++c)
		{
			const btScalar gap = gapToPoints(c);
			if (gap > bestGap)
			{
				bestGap = gap;
				best = c;
			}
		}
		if (best < 0) break;
		manifold.addManifoldPoint(makePoint(best));
		++added;
	}

	// Spread: a full manifold whose points cover a small part of the patch (Bullet keeps each new
	// GJK point, and replaces the point that leaves the largest area with it, which may leave
	// three rim points and an inner one: a cylinder then rests on a triangle through its own
	// centre) trades a point for a candidate while that enlarges the points' hull by 1%, the
	// deepest point kept as Bullet keeps it.
	if (manifold.getNumContacts() == MANIFOLD_CACHE_SIZE)
	{
		for (int round = 0; round < MANIFOLD_CACHE_SIZE; ++round)
		{
			btScalar u[MANIFOLD_CACHE_SIZE], v[MANIFOLD_CACHE_SIZE];
			int deepest = 0;
			for (int j = 0; j < MANIFOLD_CACHE_SIZE; ++j)
			{
				const btManifoldPoint& p = manifold.getContactPoint(j);
				u[j] = p.getPositionWorldOnA().dot(t1);
				v[j] = p.getPositionWorldOnA().dot(t2);
				if (p.getDistance() < manifold.getContactPoint(deepest).getDistance()) deepest = j;
			}
			const btScalar current = hullArea4(u, v);
			btScalar bestArea = current * btScalar(1.01) + SIMD_EPSILON;
			int bestCandidate = -1, bestSlot = -1;
			for (int c = 0; c < numCandidates; ++c)
			{
				if (!(gapToPoints(c) > sameSpot2)) continue;
				for (int j = 0; j < MANIFOLD_CACHE_SIZE; ++j)
				{
					// A point deeper than keepDepth carries penetration to remove: it stays.
					if (j == deepest || manifold.getContactPoint(j).getDistance() < -keepDepth) continue;
					const btScalar keepU = u[j], keepV = v[j];
					u[j] = candidateA[c].dot(t1);
					v[j] = candidateA[c].dot(t2);
					const btScalar area = hullArea4(u, v);
					u[j] = keepU;
					v[j] = keepV;
					if (area > bestArea)
					{
						bestArea = area;
						bestCandidate = c;
						bestSlot = j;
					}
				}
			}
			if (bestCandidate < 0) break;
			manifold.removeContactPoint(bestSlot);  // Bullet's own removal: the app's destroyed callback runs
			manifold.addManifoldPoint(makePoint(bestCandidate));
			++added;
		}
	}
	return added;
}
