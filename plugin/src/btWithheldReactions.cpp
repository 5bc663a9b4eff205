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

#include "btWithheldReactions.h"

#include "BulletDynamics/Dynamics/btRigidBody.h"

void btWithheldReactions::reset(int numNodes, int numContactRows)
{
	m_heldBack.resize(numContactRows);
	for (int i = 0; i < numContactRows; ++i) m_heldBack[i] = btScalar(0);
	m_linear.resize(numNodes);
	m_angular.resize(numNodes);
	m_has.resize(numNodes);
	for (int i = 0; i < numNodes; ++i)
	{
		m_linear[i].setZero();
		m_angular[i].setZero();
		m_has[i] = 0;
	}
}

void btWithheldReactions::deliver(int node, btSolverBody& body)
{
	const btRigidBody* rb = body.m_originalBody;
	if (rb)
	{
		// The velocity change Bullet's kernels would have made (btSolverBody::internalApplyImpulse
		// with a row's W J^T): the factors enter twice, once in the row and once in the body.
		const btVector3& lf = rb->getLinearFactor();
		const btVector3& af = rb->getAngularFactor();
		body.internalGetDeltaLinearVelocity() += m_linear[node] * rb->getInvMass() * lf * lf;
		body.internalGetDeltaAngularVelocity() += (rb->getInvInertiaTensorWorld() * m_angular[node]) * af * af;
	}
	discard(node);
}

void btWithheldReactions::discard(int node)
{
	m_linear[node].setZero();
	m_angular[node].setZero();
	m_has[node] = 0;
}
