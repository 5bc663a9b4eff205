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

// A fixated body's mobility: the directions its supports do not resist (btShockPredictor.h).
//
// Fixation stands for the ground holding a body through its supports. A body grounded on
// frictionless supports is held vertically and in tilt, but nothing holds it sideways or in
// yaw: an impulse from above along those directions is not passed on to the ground, it moves
// the body. Fixated with infinite mass in every direction, it kept still under a sideways
// squeeze from the layer above; delivered afterwards, the squeeze pushed it out and no layer
// below could take it back (the round tower on ice, docs/design.md section 4.2).
//
// With W = diag(1/m I, I_world^-1) the body's inverse mass and G the Jacobians (its side) of the
// support rows that can resist (contact rows, and friction or rolling rows whose coefficient is
// above 0), the supports hold the W-orthogonal span of W G^T and leave the rest:
//   W' = W - W G^T (G W G^T)^+ G W,
// formed by Gram-Schmidt in the W inner product <g, h> = g^T W h: each resisting row's Jacobian
// less its projection on those before, kept if its remaining norm squared is above
// spanMinPivot() (1e-3) of its own (the span test's pivot, btGroundedFixation.cpp), normalised
// as h_k; then W' = W - sum_k (W h_k)(W h_k)^T. Where the supports resist all six directions
// W' = 0, and fixation is as before.
//
// In a row with this body as its fixated side, the free body's update is exact for a support of
// inverse mass W' (s = (D_A + D_B + c) / (D_A + J_B W' J_B^T + c)), the support moves by
// W' J_B^T dL at once, and the rest, (W - W') J_B^T dL, is withheld and delivered later: every
// impulse still acts on both bodies in full once delivered.
// Bodies grounded only as members of a cluster keep W' = 0: their cluster mates, not their
// supports, hold them.

#include "btShockPredictor.h"

#include "BulletDynamics/Dynamics/btRigidBody.h"

namespace
{
btScalar innerW(const btVector3& gLinear, const btVector3& gAngular, const btVector3& hLinear, const btVector3& hAngular, btScalar invMass,
				const btMatrix3x3& invInertia)
{
	return invMass * gLinear.dot(hLinear) + gAngular.dot(invInertia * hAngular);
}
}  // namespace

int btShockPredictor::supportBasis(int body, btScalar invMass, const btMatrix3x3& invInertia, bool resistingOnly, SupportDirection basis[6],
								   bool& oneSided) const
{
	int rank = 0;
	oneSided = false;
	for (int k = m_supportStart[body]; k < m_supportStart[body + 1] && rank < 6; ++k)
	{
		const Row& r = m_rows[m_supportRows[k]];
		if (!r.m_fixed) continue;
		oneSided = true;
		if (resistingOnly && r.m_normal && !(r.m_row->m_friction > btScalar(0))) continue;  // cannot resist
		SupportDirection g;
		freeSide(r, g.m_linear, g.m_angular);
		const btScalar norm = innerW(g.m_linear, g.m_angular, g.m_linear, g.m_angular, invMass, invInertia);
		if (!(norm > btScalar(0))) continue;
		for (int j = 0; j < rank; ++j)
		{
			const btScalar p = innerW(g.m_linear, g.m_angular, basis[j].m_linear, basis[j].m_angular, invMass, invInertia);
			g.m_linear -= basis[j].m_linear * p;
			g.m_angular -= basis[j].m_angular * p;
		}
		const btScalar left = innerW(g.m_linear, g.m_angular, g.m_linear, g.m_angular, invMass, invInertia);
		if (!(left > spanMinPivot() * norm)) continue;
		const btScalar scale = btScalar(1) / btSqrt(left);
		basis[rank].m_linear = g.m_linear * scale;
		basis[rank].m_angular = g.m_angular * scale;
		++rank;
	}
	return rank;
}

void btShockPredictor::formMobility(const btAlignedObjectArray<btSolverBody>& bodies)
{
	m_mobile.resize(bodies.size());
	m_mobility.resize(0);
	for (int b = 0; b < bodies.size(); ++b)
	{
		m_mobile[b] = -1;
		const btRigidBody* rb = bodies[b].m_originalBody;
		if (!rb || !(rb->getInvMass() > btScalar(0)) || m_grounded[b] != 1 || m_supportStart[b] == m_supportStart[b + 1]) continue;
		if (!(bodies[b].m_linearFactor == btVector3(1, 1, 1) && bodies[b].m_angularFactor == btVector3(1, 1, 1))) continue;
		// Supports that all resist fix every direction (the body is grounded alone: they span six).
		bool yielding = false;
		for (int k = m_supportStart[b]; k < m_supportStart[b + 1] && !yielding; ++k)
		{
			const Row& r = m_rows[m_supportRows[k]];
			yielding = r.m_fixed && r.m_normal && !(r.m_row->m_friction > btScalar(0));
		}
		if (!yielding) continue;
		if (!supportFactor(b)) continue;  // grounded as a cluster's member
		const btScalar invMass = rb->getInvMass();
		const btMatrix3x3& invInertia = rb->getInvInertiaTensorWorld();
		SupportDirection basis[6];
		bool oneSided = false;
		const int rank = supportBasis(b, invMass, invInertia, true, basis, oneSided);
		if (!oneSided || rank == 6) continue;
		// W' = W - sum_k (W h_k)(W h_k)^T in blocks: linear-linear, linear-angular, angular-angular.
		Mobility mobility;
		mobility.m_vv = btMatrix3x3(invMass, 0, 0, 0, invMass, 0, 0, 0, invMass);
		mobility.m_vw = btMatrix3x3(0, 0, 0, 0, 0, 0, 0, 0, 0);
		mobility.m_ww = invInertia;
		for (int k = 0; k < rank; ++k)
		{
			const btVector3 v = basis[k].m_linear * invMass;
			const btVector3 w = invInertia * basis[k].m_angular;
			for (int i = 0; i < 3; ++i)
				for (int j = 0; j < 3; ++j)
				{
					mobility.m_vv[i][j] -= v[i] * v[j];
					mobility.m_vw[i][j] -= v[i] * w[j];
					mobility.m_ww[i][j] -= w[i] * w[j];
				}
		}
		m_mobile[b] = m_mobility.size();
		m_mobility.push_back(mobility);
	}
	// Each one-sided row whose fixated side is mobile: the free body's update for a support of
	// inverse mass W'. Without mobile bodies every row keeps the m_fixedTerm of 0 that addRow and
	// freeBothSides give it, and the pass over the rows is skipped.
	for (int i = 0; i < m_rows.size() && m_mobility.size(); ++i)
	{
		Row& r = m_rows[i];
		r.m_fixedTerm = 0;
		if (!r.m_fixed || !(r.m_scale > btScalar(0)) || m_mobile[fixedSide(r)] < 0) continue;
		btVector3 dv, dw;
		mobileResponse(r, btScalar(1), dv, dw);
		const bool sideA = r.m_fixed == 1;
		const btSolverConstraint& c = *r.m_row;
		r.m_fixedTerm = (sideA ? c.m_contactNormal1 : c.m_contactNormal2).dot(dv) + (sideA ? c.m_relpos1CrossNormal : c.m_relpos2CrossNormal).dot(dw);
		if (!(r.m_fixedTerm > btScalar(0))) r.m_fixedTerm = 0;
		const btScalar freeTerm = r.m_total / r.m_scale;
		r.m_scale = r.m_total / (freeTerm + r.m_fixedTerm);
	}
}

void btShockPredictor::mobileResponse(const Row& r, btScalar impulse, btVector3& dv, btVector3& dw) const
{
	const Mobility& mobility = m_mobility[m_mobile[fixedSide(r)]];
	const bool sideA = r.m_fixed == 1;
	const btSolverConstraint& c = *r.m_row;
	const btVector3 f = (sideA ? c.m_contactNormal1 : c.m_contactNormal2) * impulse;
	const btVector3 t = (sideA ? c.m_relpos1CrossNormal : c.m_relpos2CrossNormal) * impulse;
	dv = mobility.m_vv * f + mobility.m_vw * t;
	dw = f * mobility.m_vw + mobility.m_ww * t;  // v * M is M^T v
}

void btShockPredictor::moveMobile(const Row& r, btScalar impulse, btAlignedObjectArray<btSolverBody>& bodies) const
{
	btVector3 dv, dw;
	mobileResponse(r, impulse, dv, dw);
	btSolverBody& body = bodies[fixedSide(r)];
	body.internalGetDeltaLinearVelocity() += dv;
	body.internalGetDeltaAngularVelocity() += dw;
}
