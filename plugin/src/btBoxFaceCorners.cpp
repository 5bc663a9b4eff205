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

#include "btBoxFaceCorners.h"
#include "btContactPatch.h"

#include "BulletShockPropagation/btShockPropagationSettings.h"

#include "BulletCollision/CollisionDispatch/btCollisionObject.h"
#include "BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h"
#include "BulletCollision/CollisionDispatch/btManifoldResult.h"
#include "BulletCollision/CollisionShapes/btBoxShape.h"
#include "BulletCollision/NarrowPhaseCollision/btPersistentManifold.h"

namespace
{
// A face counts as lying along the manifold's normal within about 8 degrees
// (btShockPropagationNumerics::faceAlignment, cos 8 deg = 0.99): beyond that the pair touches along
// an edge or at a corner, and its other corners are not near the face.

const btBoxShape* boxOf(const btCollisionObject* object)
{
	const btCollisionShape* shape = object->getCollisionShape();
	return shape && shape->getShapeType() == BOX_SHAPE_PROXYTYPE ? static_cast<const btBoxShape*>(shape) : 0;
}

/// The axis of `box` (at `frame`) whose face looks most along `towards`, with the face's outward
/// sign; false if no face lies within btShockPropagationNumerics::faceAlignment() of it.
bool faceTowards(const btTransform& frame, const btVector3& towards, int& axis, btScalar& sign)
{
	btScalar best = 0;
	for (int a = 0; a < 3; ++a)
	{
		const btScalar d = frame.getBasis().getColumn(a).dot(towards);
		if (btFabs(d) > btFabs(best))
		{
			best = d;
			axis = a;
		}
	}
	sign = best >= btScalar(0) ? btScalar(1) : btScalar(-1);
	return btFabs(best) >= btShockPropagationNumerics::faceAlignment();
}
}  // namespace

int btKeepBoxFaceCorners(btPersistentManifold& manifold, btScalar reach)
{
	const int initial = manifold.getNumContacts();
	if (initial < 1 || initial >= MANIFOLD_CACHE_SIZE || !(reach > btScalar(0))) return 0;
	const btCollisionObject* objectA = manifold.getBody0();
	const btCollisionObject* objectB = manifold.getBody1();
	const btBoxShape* boxes[2] = {boxOf(objectA), boxOf(objectB)};
	if (!boxes[0] || !boxes[1]) return 0;
	const btManifoldPoint reference = manifold.getContactPoint(0);
	const btVector3 n = reference.m_normalWorldOnB;  // from B into A
	if (!(btFabs(n.length2() - btScalar(1)) < btScalar(1e-3))) return 0;
	const btCollisionObject* objects[2] = {objectA, objectB};
	const btScalar breaking = manifold.getContactBreakingThreshold();
	const btScalar sameSpot2 = breaking * breaking;
	int added = 0;
	// side 0: A's corners against B's face; side 1: B's corners against A's face.
	for (int side = 0; side < 2 && manifold.getNumContacts() < MANIFOLD_CACHE_SIZE; ++side)
	{
		const btTransform& cornerFrame = objects[side]->getWorldTransform();
		const btTransform& faceFrame = objects[1 - side]->getWorldTransform();
		const btVector3 cornerHalf = boxes[side]->getHalfExtentsWithMargin();
		const btVector3 faceHalf = boxes[1 - side]->getHalfExtentsWithMargin();
		// The corner box's face towards the other box and the other box's face towards it.
		const btVector3 towardsFace = side == 0 ? -n : n;
		int cornerAxis = 0, faceAxis = 0;
		btScalar cornerSign = 1, faceSign = 1;
		if (!faceTowards(cornerFrame, towardsFace, cornerAxis, cornerSign) || !faceTowards(faceFrame, -towardsFace, faceAxis, faceSign)) continue;
		const btVector3 faceNormal = faceFrame.getBasis().getColumn(faceAxis) * faceSign;  // outward, towards the corner box
		const btVector3 faceCentre = faceFrame.getOrigin() + faceNormal * faceHalf[faceAxis];
		const int u = (cornerAxis + 1) % 3, v = (cornerAxis + 2) % 3;
		for (int c = 0; c < 4 && manifold.getNumContacts() < MANIFOLD_CACHE_SIZE; ++c)
		{
			btVector3 local;
			local[cornerAxis] = cornerSign * cornerHalf[cornerAxis];
			local[u] = (c & 1) ? cornerHalf[u] : -cornerHalf[u];
			local[v] = (c & 2) ? cornerHalf[v] : -cornerHalf[v];
			const btVector3 corner = cornerFrame * local;
			// Its distance from the face (positive: apart), along the face's outward normal.
			const btScalar distance = (corner - faceCentre).dot(faceNormal);
			if (!(distance <= reach && distance >= -breaking)) continue;
			// Over the face: within its extents across its normal.
			const btVector3 onFace = faceFrame.invXform(corner - faceNormal * distance);
			bool over = true;
			for (int a = 0; a < 3; ++a)
				if (a != faceAxis && btFabs(onFace[a]) > faceHalf[a]) over = false;
			if (!over) continue;
			// The manifold's convention: on A = on B + n * distance.
			const btVector3 onA = side == 0 ? corner : corner + n * distance;
			const btVector3 onB = onA - n * distance;
			bool present = false;
			for (int j = 0; j < manifold.getNumContacts() && !present; ++j)
				present = (manifold.getContactPoint(j).getPositionWorldOnA() - onA).length2() < sameSpot2;
			if (present) continue;
			const btManifoldPoint point = btAddedContactPoint(reference, objectA, objectB, onA, onB, distance, n);
			manifold.addManifoldPoint(point);
			++added;
		}
	}
	return added;
}
