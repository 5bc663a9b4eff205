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

#include "btPositionCorrection.h"

#include "btShockPredictor.h"

#include "BulletDynamics/Dynamics/btRigidBody.h"
#include "BulletShockPropagation/btStackLayers.h"
#include "LinearMath/btTransformUtil.h"

void btPositionCorrection::reset(int numBodies, int numLayers, int numPoints)
{
	Body empty;
	empty.m_body = 0;
	empty.m_invMass = btScalar(0);
	empty.m_invInertia.setZero();
	empty.m_linearFactor.setZero();
	empty.m_angularFactor.setZero();
	empty.m_shift.setZero();
	empty.m_turn.setZero();
	empty.m_change.setIdentity();
	m_bodies.resize(numBodies, empty);
	m_fixated.resize(numBodies);
	m_touching.resize(numBodies);
	for (int i = 0; i < numBodies; ++i)
	{
		m_bodies[i] = empty;
		m_fixated[i] = 0;
		m_touching[i] = 0;
	}
	m_points.resize(0);
	m_joints.resize(0);
	m_carried.resize(0);
	if (m_points.capacity() < numPoints) m_points.reserve(numPoints);
	if (m_sorted.capacity() < numPoints) m_sorted.reserve(numPoints);
	m_numLayers = btMax(1, numLayers);
}

void btPositionCorrection::setBody(int node, btRigidBody* rb)
{
	Body& b = m_bodies[node];
	b.m_body = rb;
	b.m_invMass = rb->getInvMass();
	b.m_invInertia = rb->getInvInertiaTensorWorld();
	b.m_linearFactor = rb->getLinearFactor();
	b.m_angularFactor = rb->getAngularFactor();
	b.m_shift.setZero();
	b.m_turn.setZero();
}

void btPositionCorrection::addPoint(int nodeA, int nodeB, const btVector3& pointOnA, const btVector3& pointOnB, const btVector3& normalOnB,
									btScalar target, int layer)
{
	Point& p = m_points.expandNonInitializing();
	p.m_bodyA = (nodeA >= 0 && m_bodies[nodeA].m_body) ? nodeA : -1;
	p.m_bodyB = (nodeB >= 0 && m_bodies[nodeB].m_body) ? nodeB : -1;
	p.m_normal = normalOnB;
	p.m_armA = p.m_bodyA >= 0 ? pointOnA - m_bodies[p.m_bodyA].m_body->getCenterOfMassPosition() : btVector3(0, 0, 0);
	p.m_armB = p.m_bodyB >= 0 ? pointOnB - m_bodies[p.m_bodyB].m_body->getCenterOfMassPosition() : btVector3(0, 0, 0);
	p.m_target = target;
	p.m_lambda = btScalar(0);
	p.m_layer = (layer >= 0 && layer < m_numLayers) ? layer : 0;
}

void btPositionCorrection::addJoint(int nodeA, int nodeB)
{
	m_joints.push_back((nodeA >= 0 && m_bodies[nodeA].m_body) ? nodeA : -1);
	m_joints.push_back((nodeB >= 0 && m_bodies[nodeB].m_body) ? nodeB : -1);
}

void btPositionCorrection::formTerms()
{
	// Each point's Jacobian terms depend only on its arms, its normal and its bodies' inverse
	// masses and inertias, none of which a sweep changes: formed once per solve.
	m_terms.resizeNoInitialize(m_points.size());
	for (int i = 0; i < m_points.size(); ++i)
	{
		const Point& p = m_points[i];
		Terms& t = m_terms[i];
		t.m_crossA = p.m_armA.cross(p.m_normal);
		t.m_crossB = p.m_armB.cross(p.m_normal);
		t.m_angularA.setZero();
		t.m_angularB.setZero();
		t.m_termA = t.m_termB = btScalar(0);
		if (p.m_bodyA >= 0)
		{
			const Body& a = m_bodies[p.m_bodyA];
			t.m_angularA = (a.m_invInertia * t.m_crossA) * a.m_angularFactor;
			t.m_termA = a.m_invMass * (p.m_normal * a.m_linearFactor).dot(p.m_normal) + t.m_crossA.dot(t.m_angularA);
		}
		if (p.m_bodyB >= 0)
		{
			const Body& b = m_bodies[p.m_bodyB];
			t.m_angularB = (b.m_invInertia * t.m_crossB) * b.m_angularFactor;
			t.m_termB = b.m_invMass * (p.m_normal * b.m_linearFactor).dot(p.m_normal) + t.m_crossB.dot(t.m_angularB);
		}
	}
}

bool btPositionCorrection::sweepPoints(int begin, int end)
{
	bool changed = false;
	for (int i = begin; i < end; ++i)
	{
		Point& p = m_points[m_sorted[i]];
		const Terms& t = m_terms[m_sorted[i]];
		// Separation gained so far along the normal: n . (dx_A + dtheta_A x r_A - dx_B - dtheta_B x r_B).
		btScalar gained = btScalar(0);
		if (p.m_bodyA >= 0)
		{
			const Body& a = m_bodies[p.m_bodyA];
			gained += p.m_normal.dot(a.m_shift) + t.m_crossA.dot(a.m_turn);
		}
		if (p.m_bodyB >= 0)
		{
			const Body& b = m_bodies[p.m_bodyB];
			gained -= p.m_normal.dot(b.m_shift) + t.m_crossB.dot(b.m_turn);
		}
		bool moveA = p.m_bodyA >= 0 && !m_fixated[p.m_bodyA];
		bool moveB = p.m_bodyB >= 0 && !m_fixated[p.m_bodyB];
		// A lower body is fixated only while s = (D_A + D_B) / D_free is at most m_maxScale; beyond,
		// both bodies move, as the converging step's velocity rows do (btShockPredictor::addRow; a
		// free side that nothing can move keeps the other fixated there too), so that the positions
		// do not hold up a body whose velocity the contact does not stop.
		if (moveA != moveB && p.m_bodyA >= 0 && p.m_bodyB >= 0 &&
			btShockPredictor::fixationScale(moveA ? t.m_termA : t.m_termB, t.m_termA + t.m_termB) > m_maxScale)
			moveA = moveB = true;
		const btScalar inverseMass = (moveA ? t.m_termA : btScalar(0)) + (moveB ? t.m_termB : btScalar(0));
		if (!(inverseMass > SIMD_EPSILON)) continue;
		btScalar delta = (p.m_target - gained) / inverseMass;
		const btScalar sum = p.m_lambda + delta;
		if (sum < btScalar(0)) delta = -p.m_lambda;
		p.m_lambda += delta;
		if (delta == btScalar(0)) continue;
		changed = true;
		if (moveA)
		{
			Body& a = m_bodies[p.m_bodyA];
			a.m_shift += p.m_normal * a.m_linearFactor * (a.m_invMass * delta);
			a.m_turn += t.m_angularA * delta;
		}
		if (moveB)
		{
			Body& b = m_bodies[p.m_bodyB];
			b.m_shift -= p.m_normal * b.m_linearFactor * (b.m_invMass * delta);
			b.m_turn -= t.m_angularB * delta;
		}
	}
	return changed;
}

void btPositionCorrection::solve(int sweeps, const btStackLayers* layers, btScalar maxFixationScale)
{
	m_maxScale = maxFixationScale;
	formTerms();
	const int numLayers = layers ? m_numLayers : 1;
	// Points by layer (counting sort; order within a layer kept).
	m_layerStart.resize(numLayers + 1);
	for (int k = 0; k <= numLayers; ++k) m_layerStart[k] = 0;
	for (int i = 0; i < m_points.size(); ++i) ++m_layerStart[(layers ? m_points[i].m_layer : 0) + 1];
	for (int k = 0; k < numLayers; ++k) m_layerStart[k + 1] += m_layerStart[k];
	m_sorted.resize(m_points.size());
	m_cursor.resize(numLayers);
	for (int k = 0; k < numLayers; ++k) m_cursor[k] = m_layerStart[k];
	for (int i = 0; i < m_points.size(); ++i) m_sorted[m_cursor[layers ? m_points[i].m_layer : 0]++] = i;
	for (int k = 0; k < numLayers; ++k)
	{
		const int begin = m_layerStart[k], end = m_layerStart[k + 1];
		if (begin == end) continue;
		if (layers && k < layers->getNumLayers())
			for (int i = 0; i < layers->getNumFixatedBodies(k); ++i) m_fixated[layers->getFixatedBody(k, i)] = 1;
		// A sweep that changes no point leaves every body as it was, so each later one would too.
		for (int s = 0; s < sweeps; ++s)
			if (!sweepPoints(begin, end)) break;
		if (layers && k < layers->getNumLayers())
			for (int i = 0; i < layers->getNumFixatedBodies(k); ++i) m_fixated[layers->getFixatedBody(k, i)] = 0;
	}
	carryByJoints();
}

int btPositionCorrection::findHanging(int node)
{
	while (m_hanging[node] != node)
	{
		m_hanging[node] = m_hanging[m_hanging[node]];
		node = m_hanging[node];
	}
	return node;
}

void btPositionCorrection::carryByJoints()
{
	// The bodies that touch nothing, joined by the joints among them into hanging groups. A group
	// attached by exactly one joint to the rest of the world, and that to a dynamic body that
	// touches something and is no lighter than the whole group, moves rigidly with that body:
	// every joint in the group and the attaching one are left as they were. A group held at two
	// places (the middle of a bridge between two planks on their supports, a chain anchored to
	// the ground) is not moved: a rigid motion with one of them would open the other.
	m_carried.resize(0);
	m_carriedBy.resize(0);
	if (m_joints.size() == 0) return;
	const int n = m_bodies.size();
	m_hanging.resize(n);
	m_carrier.resize(n);
	m_attachments.resize(n);
	m_hangingMass.resize(n);
	for (int i = 0; i < n; ++i)
	{
		m_hanging[i] = i;
		m_carrier[i] = -1;
		m_attachments[i] = 0;
		m_hangingMass[i] = 0;
	}
	for (int j = 0; j + 1 < m_joints.size(); j += 2)
	{
		const int a = m_joints[j], b = m_joints[j + 1];
		if (a >= 0 && b >= 0 && !m_touching[a] && !m_touching[b]) m_hanging[findHanging(a)] = findHanging(b);
	}
	for (int j = 0; j + 1 < m_joints.size(); j += 2)
		for (int side = 0; side < 2; ++side)
		{
			const int body = m_joints[j + side], other = m_joints[j + 1 - side];
			if (body < 0 || m_touching[body] || (other >= 0 && !m_touching[other])) continue;
			const int root = findHanging(body);
			++m_attachments[root];
			m_carrier[root] = other;  // -1: static, kinematic or outside the group
		}
	for (int i = 0; i < n; ++i)
		if (!m_touching[i] && m_bodies[i].m_invMass > btScalar(0)) m_hangingMass[findHanging(i)] += btScalar(1) / m_bodies[i].m_invMass;
	for (int i = 0; i < n; ++i)
	{
		if (m_touching[i]) continue;
		const int root = findHanging(i);
		const int carrier = m_carrier[root];
		if (m_attachments[root] != 1 || carrier < 0 || !(m_bodies[carrier].m_invMass * m_hangingMass[root] <= btScalar(1))) continue;
		m_carried.push_back(i);
		m_carriedBy.push_back(carrier);
	}
}

void btPositionCorrection::apply()
{
	// A body's change of pose is kept only while some body is carried (carryByJoints).
	const bool carrying = m_carried.size() > 0;
	for (int i = 0; i < m_bodies.size(); ++i)
	{
		Body& b = m_bodies[i];
		if (carrying) b.m_change.setIdentity();
		if (!b.m_body || (b.m_shift.isZero() && b.m_turn.isZero())) continue;
		btTransform corrected;
		btTransformUtil::integrateTransform(b.m_body->getWorldTransform(), b.m_shift, b.m_turn, btScalar(1), corrected);
		if (carrying) b.m_change = corrected * b.m_body->getWorldTransform().inverse();
		// As Bullet's own integration does: the world inertia follows the new orientation.
		b.m_body->setCenterOfMassTransform(corrected);
	}
	// Carried bodies (no contact rows, so no correction of their own) take their carrier's
	// change of pose.
	for (int k = 0; k < m_carried.size(); ++k)
	{
		const btTransform& change = m_bodies[m_carriedBy[k]].m_change;
		btRigidBody* body = m_bodies[m_carried[k]].m_body;
		body->setCenterOfMassTransform(change * body->getWorldTransform());
	}
}
