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

// Velocity-based shock propagation: K. Erleben, "Velocity-Based Shock Propagation for Multibody
// Dynamics Animation", ACM TOG 26(2), Article 12, 2007. The algorithm as built, and decisions
// D1-D10, are described in btShockPropagationConstraintSolver.h.

#include "BulletShockPropagation/btShockPropagationConstraintSolver.h"

#include "BulletCollision/NarrowPhaseCollision/btPersistentManifold.h"
#include "BulletDynamics/Dynamics/btRigidBody.h"
#include "BulletShockPropagation/btLayerFixation.h"
#include "LinearMath/btQuickprof.h"
#include "LinearMath/btTransformUtil.h"

#include <cstdio>

namespace
{
bool isFiniteScalar(btScalar x)
{
	return x == x && x - x == btScalar(0);  // false for NaN and for +-Inf
}

bool isFiniteVector(const btVector3& v)
{
	return isFiniteScalar(v.x() + v.y() + v.z());
}

/// Transform and velocities finite (a NaN or Inf anywhere makes the sum non-finite).
bool isHealthy(const btCollisionObject* object)
{
	const btTransform& t = object->getWorldTransform();
	const btMatrix3x3& m = t.getBasis();
	btScalar sum = t.getOrigin().x() + t.getOrigin().y() + t.getOrigin().z();
	for (int i = 0; i < 3; ++i) sum += m[i].x() + m[i].y() + m[i].z();
	if (const btRigidBody* rb = btRigidBody::upcast(object))
	{
		const btVector3& v = rb->getLinearVelocity();
		const btVector3& w = rb->getAngularVelocity();
		sum += v.x() + v.y() + v.z() + w.x() + w.y() + w.z();
	}
	return isFiniteScalar(sum);
}

/// A graph node: a dynamic body with finite mass (static, kinematic and zero-mass bodies are roots).
bool isNode(const btCollisionObject* object)
{
	const btRigidBody* rb = btRigidBody::upcast(object);
	return rb && !object->isStaticOrKinematicObject() && rb->getInvMass() != btScalar(0);
}

bool hasFinitePoints(const btPersistentManifold* manifold)
{
	for (int j = 0; j < manifold->getNumContacts(); ++j)
	{
		const btManifoldPoint& cp = manifold->getContactPoint(j);
		if (!isFiniteScalar(cp.getDistance()) || !isFiniteVector(cp.m_normalWorldOnB) ||
			!isFiniteVector(cp.getPositionWorldOnA()) || !isFiniteVector(cp.getPositionWorldOnB()))
		{
			return false;
		}
	}
	return true;
}

/// One projected Gauss-Seidel update of a position row of correction():
///   x_i <- max(0, x_i + (d_i - J_i dq) / A_ii),   dq = W J^T x   (push and turn "velocities").
/// Unlike Bullet's split-impulse row it also enforces rows with zero depth (J_i dq >= 0).
void resolvePositionRow(btSolverBody& bodyA, btSolverBody& bodyB, btSolverConstraint& c)
{
	btScalar delta = c.m_rhsPenetration - btScalar(c.m_appliedPushImpulse) * c.m_cfm;
	delta -= (c.m_contactNormal1.dot(bodyA.internalGetPushVelocity()) + c.m_relpos1CrossNormal.dot(bodyA.internalGetTurnVelocity())) * c.m_jacDiagABInv;
	delta -= (c.m_contactNormal2.dot(bodyB.internalGetPushVelocity()) + c.m_relpos2CrossNormal.dot(bodyB.internalGetTurnVelocity())) * c.m_jacDiagABInv;
	const btScalar sum = btScalar(c.m_appliedPushImpulse) + delta;
	if (sum < c.m_lowerLimit)
	{
		delta = c.m_lowerLimit - btScalar(c.m_appliedPushImpulse);
		c.m_appliedPushImpulse = c.m_lowerLimit;
	}
	else
	{
		c.m_appliedPushImpulse = sum;
	}
	bodyA.internalApplyPushImpulse(c.m_contactNormal1 * bodyA.internalGetInvMass(), c.m_angularComponentA, delta);
	bodyB.internalApplyPushImpulse(c.m_contactNormal2 * bodyB.internalGetInvMass(), c.m_angularComponentB, delta);
}

/// Warm starts are clamped to this many times the lighter body's weight impulse (see prepareWarmStart).
const btScalar kWarmStartWeights = btScalar(4);

/// Weight (N) of the lighter dynamic body of a manifold; infinity if neither has finite mass.
btScalar lighterWeight(const btPersistentManifold* manifold)
{
	btScalar lightest = SIMD_INFINITY;
	const btCollisionObject* ends[2] = {manifold->getBody0(), manifold->getBody1()};
	for (const btCollisionObject* end : ends)
	{
		const btRigidBody* rb = btRigidBody::upcast(end);
		if (rb && rb->getInvMass() > btScalar(0)) lightest = btMin(lightest, rb->getGravity().length() / rb->getInvMass());
	}
	return lightest;
}

/// During a step, after the layer pass: the point's layer-pass impulse, total T minus the global
/// share G that m_prevRHS holds (D5, D13).
btScalar layerShare(const btManifoldPoint& cp)
{
	return btMax(btScalar(0), cp.m_appliedImpulse - cp.m_prevRHS);
}

/// Calls visit(row, kind) for every row of Bullet's four row pools.
template <class Visit>
void visitRows(btConstraintArray& contacts, btConstraintArray& frictions, btConstraintArray& rollingFrictions, btConstraintArray& joints,
			   Visit visit)
{
	for (int i = 0; i < contacts.size(); ++i) visit(contacts[i], BT_ROW_CONTACT);
	for (int i = 0; i < frictions.size(); ++i) visit(frictions[i], BT_ROW_FRICTION);
	for (int i = 0; i < rollingFrictions.size(); ++i) visit(rollingFrictions[i], BT_ROW_ROLLING_FRICTION);
	for (int i = 0; i < joints.size(); ++i) visit(joints[i], BT_ROW_JOINT);
}

double millisecondsSince(btClock& clock)
{
	return double(clock.getTimeMicroseconds()) * 1e-3;
}
}  // namespace

btShockPropagationConstraintSolver::btShockPropagationConstraintSolver()
{
}

btShockPropagationConstraintSolver::btShockPropagationConstraintSolver(const btShockPropagationSettings& settings)
{
	setSettings(settings);
}

btShockPropagationConstraintSolver::~btShockPropagationConstraintSolver()
{
}

void btShockPropagationConstraintSolver::setWeighting(btScalar f)
{
	if (f != f)
	{
		return;  // NaN: keep the current value
	}
	m_settings.m_weighting = btMax(btScalar(0), btMin(btScalar(1), f));
}

void btShockPropagationConstraintSolver::setSettings(const btShockPropagationSettings& settings)
{
	const btScalar f = m_settings.m_weighting;
	m_settings = settings;
	m_settings.m_weighting = f;
	setWeighting(settings.m_weighting);
	m_settings.m_globalIterations = btMax(0, settings.m_globalIterations);
	m_settings.m_layerIterations = btMax(0, settings.m_layerIterations);
	m_settings.m_correctionIterations = btMax(0, settings.m_correctionIterations);
	if (!(settings.m_correctionFraction >= 0 && settings.m_correctionFraction <= 1))
		m_settings.m_correctionFraction = btShockPropagationSettings().m_correctionFraction;
	if (!(settings.m_correctionSlop >= 0) || !isFiniteScalar(settings.m_correctionSlop))
		m_settings.m_correctionSlop = btShockPropagationSettings().m_correctionSlop;
	m_settings.m_weightIterations = btMax(1, settings.m_weightIterations);
	if (!isFiniteScalar(settings.m_graphContactThreshold))
		m_settings.m_graphContactThreshold = btShockPropagationSettings().m_graphContactThreshold;
}

void btShockPropagationConstraintSolver::prepareSolve(int numBodies, int numManifolds)
{
	btSequentialImpulseConstraintSolver::prepareSolve(numBodies, numManifolds);
	// Used alone in a stock world, each step starts with one dynamics solveConstraints call.
	if (m_phase == BT_PHASE_DYNAMICS)
	{
		resetStatistics();
	}
}

btScalar btShockPropagationConstraintSolver::solveGroup(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds,
														int numManifolds, btTypedConstraint** constraints, int numConstraints,
														const btContactSolverInfo& info, btIDebugDraw* debugDrawer, btDispatcher* /*dispatcher*/)
{
	BT_PROFILE("btShockPropagationConstraintSolver::solveGroup");
	filterInput(bodies, numBodies, manifolds, numManifolds, constraints, numConstraints);
	if (m_phase == BT_PHASE_CORRECTION)
	{
		solveCorrection(info, debugDrawer);
	}
	else
	{
		solveDynamics(info, debugDrawer);
	}
	return btScalar(0);
}

void btShockPropagationConstraintSolver::filterInput(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds,
													 int numManifolds, btTypedConstraint** constraints, int numConstraints)
{
	m_bodies.resize(0);
	m_manifolds.resize(0);
	m_constraints.resize(0);
	int skippedBodies = 0;
	for (int i = 0; i < numBodies; ++i)
	{
		if (!isHealthy(bodies[i]))
		{
			++skippedBodies;
		}
		else if (isNode(bodies[i]))
		{
			m_bodies.push_back(bodies[i]);
		}
	}
	int skippedManifolds = 0;
	for (int i = 0; i < numManifolds; ++i)
	{
		const btPersistentManifold* m = manifolds[i];
		if (isHealthy(m->getBody0()) && isHealthy(m->getBody1()) && hasFinitePoints(m))
			m_manifolds.push_back(manifolds[i]);
		else
			++skippedManifolds;
	}
	for (int i = 0; i < numConstraints; ++i)
	{
		if (isHealthy(&constraints[i]->getRigidBodyA()) && isHealthy(&constraints[i]->getRigidBodyB()))
			m_constraints.push_back(constraints[i]);
	}
	if ((skippedBodies || skippedManifolds) && !m_warnedNonFinite)
	{
		m_warnedNonFinite = true;
		std::fprintf(stderr,
					 "BulletShockPropagation: %d body(ies) with a NaN/Inf transform or velocity and %d manifold(s) touching them "
					 "are left out of the solve (warned once; see getStatistics().m_numSkippedBodies)\n",
					 skippedBodies, skippedManifolds);
	}
	if (m_phase == BT_PHASE_DYNAMICS)
	{
		m_stats.m_numSkippedBodies += skippedBodies;
		m_stats.m_numSkippedManifolds += skippedManifolds;
	}
}

void btShockPropagationConstraintSolver::buildGraph()
{
	const int n = m_bodies.size();
	m_graph.reset(n);
	// Bullet keeps companion ids at -1 between solves; borrow them as node indices meanwhile.
	for (int i = 0; i < n; ++i) m_bodies[i]->setCompanionId(i);
	struct NodeOf
	{
		const btAlignedObjectArray<btCollisionObject*>& bodies;
		int operator()(const btCollisionObject* object) const
		{
			const int id = object->getCompanionId();
			return (id >= 0 && id < bodies.size() && bodies[id] == object) ? id : int(BT_CONTACT_GRAPH_ROOT);
		}
	} nodeOf{m_bodies};

	for (int i = 0; i < m_manifolds.size(); ++i)
	{
		const btPersistentManifold* m = m_manifolds[i];
		bool touching = false;
		for (int j = 0; j < m->getNumContacts() && !touching; ++j)
		{
			touching = m->getContactPoint(j).getDistance() <= m_settings.m_graphContactThreshold;
		}
		if (touching)
		{
			m_graph.addEdge(nodeOf(m->getBody0()), nodeOf(m->getBody1()), i, supportOf(m));
		}
	}
	for (int i = 0; i < m_constraints.size(); ++i)
	{
		const btTypedConstraint* c = m_constraints[i];
		if (c->isEnabled())
		{
			m_graph.addEdge(nodeOf(&c->getRigidBodyA()), nodeOf(&c->getRigidBodyB()), -(i + 1));
		}
	}
	for (int i = 0; i < n; ++i) m_bodies[i]->setCompanionId(-1);
	m_graph.buildAdjacency();
	m_layers.build(m_graph);
}

int btShockPropagationConstraintSolver::supportOf(const btPersistentManifold* manifold) const
{
	// Mean normal (m_normalWorldOnB points from body 1 to body 0) against the up direction of
	// the dynamic body's gravity.
	if (!m_settings.m_supportOrdering || manifold->getNumContacts() == 0) return BT_SUPPORT_NONE;
	const btRigidBody* dynamic = btRigidBody::upcast(manifold->getBody0());
	if (!dynamic || dynamic->getInvMass() == btScalar(0)) dynamic = btRigidBody::upcast(manifold->getBody1());
	if (!dynamic) return BT_SUPPORT_NONE;
	const btVector3 gravity = dynamic->getGravity();
	const btScalar g = gravity.length();
	if (!(g > SIMD_EPSILON)) return BT_SUPPORT_NONE;
	btVector3 normal(0, 0, 0);
	for (int j = 0; j < manifold->getNumContacts(); ++j) normal += manifold->getContactPoint(j).m_normalWorldOnB;
	const btScalar length = normal.length();
	if (!(length > SIMD_EPSILON)) return BT_SUPPORT_NONE;
	const btScalar up = -normal.dot(gravity) / (length * g);  // cosine of the normal's angle from up
	const btScalar threshold = btCos(m_settings.m_supportAngle);
	if (up > threshold) return BT_SUPPORT_A_ON_B;
	if (up < -threshold) return BT_SUPPORT_B_ON_A;
	return BT_SUPPORT_NONE;
}

void btShockPropagationConstraintSolver::solveDynamics(const btContactSolverInfo& info, btIDebugDraw* debugDrawer)
{
	btClock clock;
	buildGraph();
	for (int i = 0; i < m_bodies.size(); ++i)
	{
		m_layeredBodies.push_back(m_bodies[i]);
		m_layeredBodyHeights.push_back(m_layers.getHeight(i));
	}
	const int numLayers = m_layers.getNumLayers();
	m_stats.m_numGroups += 1;
	m_stats.m_numComponents += m_layers.getNumComponents();
	m_stats.m_numLayers = btMax(m_stats.m_numLayers, numLayers);
	m_stats.m_largestLayer = btMax(m_stats.m_largestLayer, m_layers.getLargestLayer());
	m_stats.m_numFixatedBodies += m_layers.getTotalFixated();
	m_stats.m_timeGraphMs += millisecondsSince(clock);

	btCollisionObject** bodies = m_bodies.size() ? &m_bodies[0] : 0;
	btPersistentManifold** manifolds = m_manifolds.size() ? &m_manifolds[0] : 0;
	btTypedConstraint** constraints = m_constraints.size() ? &m_constraints[0] : 0;
	const btScalar dt = info.m_timeStep;

	m_globalPassRan = false;
	if (numLayers <= 1 && !m_settings.m_layerFlatGroups)
	{
		// No stacks: one ordinary solve of the whole step (correction, then dynamics(dt)).
		clock.reset();
		solvePass(BT_PASS_SINGLE, bodies, m_bodies.size(), manifolds, m_manifolds.size(), constraints, m_constraints.size(), info, dt, debugDrawer);
		m_stats.m_timeLayersMs += millisecondsSince(clock);
		return;
	}
	m_stats.m_numLayeredGroups += 1;
	if (m_settings.m_weightFeeling)
	{
		recordTotalsBefore();  // before the passes overwrite the cached totals
	}

	const btScalar f = m_settings.m_weighting;
	clock.reset();
	if (f > btScalar(0))
	{
		// dynamics(f dt): every body free, the whole group coupled ("weight feeling").
		solvePass(BT_PASS_GLOBAL, bodies, m_bodies.size(), manifolds, m_manifolds.size(), constraints, m_constraints.size(), info, f * dt, debugDrawer);
		m_globalPassRan = true;
	}
	m_stats.m_timeGlobalDynamicsMs += millisecondsSince(clock);

	// Layers bottom-up: correction(layer k), dynamics((1 - f) dt, layer k) with height k fixated.
	clock.reset();
	const btScalar layerStep = btMax((btScalar(1) - f) * dt, SIMD_EPSILON * dt);
	m_manifoldInLayer.resize(m_manifolds.size());
	for (int i = 0; i < m_manifolds.size(); ++i) m_manifoldInLayer[i] = 0;
	m_weightFeelingActive = m_settings.m_weightFeeling;
	if (m_weightFeelingActive)
	{
		m_withheldLinear.resize(m_bodies.size());
		m_withheldAngular.resize(m_bodies.size());
		m_hasWithheld.resize(m_bodies.size());
		m_receivedLinear.resize(m_bodies.size());
		for (int i = 0; i < m_bodies.size(); ++i)
		{
			m_receivedLinear[i].setZero();
			m_withheldLinear[i].setZero();
			m_withheldAngular[i].setZero();
			m_hasWithheld[i] = 0;
		}
	}
	for (int k = 0; k < numLayers; ++k)
	{
		m_currentLayer = k;
		collectLayer(k, &m_manifoldInLayer);
		solvePass(BT_PASS_LAYER, m_layerBodies.size() ? &m_layerBodies[0] : 0, m_layerBodies.size(),
				  m_layerManifolds.size() ? &m_layerManifolds[0] : 0, m_layerManifolds.size(),
				  m_layerConstraints.size() ? &m_layerConstraints[0] : 0, m_layerConstraints.size(), info, layerStep, debugDrawer);
	}
	m_stats.m_timeLayersMs += millisecondsSince(clock);

	if (m_weightFeelingActive)
	{
		clock.reset();
		solveWeightPass(info, layerStep, debugDrawer);
		m_weightFeelingActive = false;
		m_stats.m_timeWeightFeelingMs += millisecondsSince(clock);
	}

	// Manifolds in no layer (beyond the graph threshold): their step impulse is the global pass's.
	for (int i = 0; i < m_manifolds.size(); ++i)
	{
		if (m_manifoldInLayer[i]) continue;
		btPersistentManifold* m = m_manifolds[i];
		for (int j = 0; j < m->getNumContacts(); ++j)
		{
			btManifoldPoint& cp = m->getContactPoint(j);
			if (m_settings.m_weightFeeling)
			{
				cp.m_prevRHS = btScalar(0);  // no layer share U
			}
			else if (m_globalPassRan)
			{
				cp.m_prevRHS = cp.m_appliedImpulse;
			}
			else
			{
				cp.m_appliedImpulse = cp.m_prevRHS = cp.m_appliedImpulseLateral1 = cp.m_appliedImpulseLateral2 = btScalar(0);
			}
		}
	}
}

void btShockPropagationConstraintSolver::solveWeightPass(const btContactSolverInfo& info, btScalar layerStep, btIDebugDraw* debugDrawer)
{
	m_layerTimeStep = layerStep;
	// D13, top-down: what the layers above withheld reaches layer k's free bodies, then layer k
	// is re-solved against its (still fixated) lower bodies, withholding its extra impulses from them.
	for (int k = m_layers.getNumLayers() - 1; k >= 0; --k)
	{
		if (!applyWithheldReactions(k))
		{
			// Nothing rests on this layer (the top layer): its solve would not change. Its
			// points keep U = T - G for the next step's layer pass.
			collectLayer(k, 0);
			for (int i = 0; i < m_layerManifolds.size(); ++i)
			{
				btPersistentManifold* m = m_layerManifolds[i];
				for (int j = 0; j < m->getNumContacts(); ++j)
				{
					btManifoldPoint& cp = m->getContactPoint(j);
					cp.m_prevRHS = layerShare(cp);
				}
			}
			continue;
		}
		m_currentLayer = k;
		collectLayer(k, 0);
		solvePass(BT_PASS_WEIGHT, m_layerBodies.size() ? &m_layerBodies[0] : 0, m_layerBodies.size(),
				  m_layerManifolds.size() ? &m_layerManifolds[0] : 0, m_layerManifolds.size(),
				  m_layerConstraints.size() ? &m_layerConstraints[0] : 0, m_layerConstraints.size(), info, layerStep, debugDrawer);
	}
}

bool btShockPropagationConstraintSolver::applyWithheldReactions(int layer)
{
	bool any = false;
	m_layerVelocityBefore.resize(m_layers.getNumFreeBodies(layer));
	for (int i = 0; i < m_layers.getNumFreeBodies(layer); ++i)
	{
		const int node = m_layers.getFreeBody(layer, i);
		btRigidBody* body = btRigidBody::upcast(m_bodies[node]);
		m_layerVelocityBefore[i].m_linear = body->getLinearVelocity();
		m_layerVelocityBefore[i].m_angular = body->getAngularVelocity();
		if (!m_hasWithheld[node]) continue;
		m_receivedLinear[node] = m_withheldLinear[node];
		body->applyCentralImpulse(m_withheldLinear[node]);
		body->applyTorqueImpulse(m_withheldAngular[node]);
		m_withheldLinear[node].setZero();
		m_withheldAngular[node].setZero();
		m_hasWithheld[node] = 0;
		any = true;
	}
	return any;
}

bool btShockPropagationConstraintSolver::weightPassAccepted(int numFreeBodies)
{
	// A load handed down pushes a body down and its supports can at most stop it: after the
	// re-solve no free body's centre of mass may rise faster than before the load arrived
	// (slack 0.1 g dt). A re-solve that lifts a body did not converge (measured: the round tower
	// of 20 rings, whose lower rings carry 19 rings at one end of each brick).
	for (int i = 0; i < numFreeBodies && i < m_tmpSolverBodyPool.size() && i < m_layerVelocityBefore.size(); ++i)
	{
		btSolverBody& sb = m_tmpSolverBodyPool[i];
		const btRigidBody* rb = sb.m_originalBody;
		if (!rb) continue;
		const btVector3 gravity = rb->getGravity();
		const btScalar g = gravity.length();
		if (!(g > SIMD_EPSILON)) continue;
		const btVector3 up = -gravity / g;
		const btScalar slack = btScalar(0.1) * g * m_layerTimeStep;
		const btVector3 after = sb.m_linearVelocity + sb.internalGetDeltaLinearVelocity();
		if (!(after.dot(up) <= m_layerVelocityBefore[i].m_linear.dot(up) + slack)) return false;
	}
	return true;
}

void btShockPropagationConstraintSolver::mapFixatedSolverBodies(int layer)
{
	// During a solve Bullet keeps each body's solver body index in its companion id.
	const int numSolverBodies = m_tmpSolverBodyPool.size();
	m_nodeOfSolverBody.resize(numSolverBodies);
	for (int id = 0; id < numSolverBodies; ++id) m_nodeOfSolverBody[id] = -1;
	for (int i = 0; i < m_layers.getNumFixatedBodies(layer); ++i)
	{
		const int node = m_layers.getFixatedBody(layer, i);
		const int id = m_bodies[node]->getCompanionId();
		if (id >= 0 && id < numSolverBodies && m_fixatedRigidBody[id]) m_nodeOfSolverBody[id] = node;
	}
}

void btShockPropagationConstraintSolver::prepareWeightPass(int numFreeBodies, const btContactSolverInfo& info)
{
	// The free bodies already received this step's gravity (layer pass) and the reactions from
	// above: take the external impulses out of the rows and bodies, and let the contact rows
	// continue from the layer pass's impulse L (total minus global share) without applying it again.
	visitRows(m_tmpSolverContactConstraintPool, m_tmpSolverContactFrictionConstraintPool, m_tmpSolverContactRollingFrictionConstraintPool,
			  m_tmpSolverNonContactConstraintPool, [&](btSolverConstraint& row, btSolverRowKind kind) {
				  const bool freeA = row.m_solverBodyIdA < numFreeBodies;
				  const bool freeB = row.m_solverBodyIdB < numFreeBodies;
				  btRemoveExternalImpulse(row, kind, m_tmpSolverBodyPool[row.m_solverBodyIdA], m_tmpSolverBodyPool[row.m_solverBodyIdB], freeA, freeB, info.m_damping);
			  });
	for (int id = 0; id < numFreeBodies && id < m_tmpSolverBodyPool.size(); ++id)
	{
		m_tmpSolverBodyPool[id].m_externalForceImpulse.setZero();
		m_tmpSolverBodyPool[id].m_externalTorqueImpulse.setZero();
	}
	for (int i = 0; i < m_tmpSolverContactConstraintPool.size(); ++i)
	{
		btSolverConstraint& row = m_tmpSolverContactConstraintPool[i];
		const btManifoldPoint* cp = static_cast<const btManifoldPoint*>(row.m_originalContactPoint);
		row.m_appliedImpulse = layerShare(*cp);
	}
}

void btShockPropagationConstraintSolver::recordTotalsBefore()
{
	// The step's previous totals T, per point, for the weight pass's warm start: the layer and
	// global passes overwrite m_appliedImpulse before it runs. Rows point at their btManifoldPoint,
	// which lies in its manifold's point cache: manifolds sorted by that address find it.
	m_manifoldByAddress.resize(m_manifolds.size());
	m_totalBefore.resize(m_manifolds.size() * MANIFOLD_CACHE_SIZE);
	for (int i = 0; i < m_manifolds.size(); ++i)
	{
		btPersistentManifold* m = m_manifolds[i];
		m_manifoldByAddress[i].m_points = &m->getContactPoint(0);
		m_manifoldByAddress[i].m_index = i;
		for (int j = 0; j < MANIFOLD_CACHE_SIZE; ++j)
			m_totalBefore[i * MANIFOLD_CACHE_SIZE + j] = j < m->getNumContacts() ? m->getContactPoint(j).m_appliedImpulse : btScalar(0);
	}
	struct ByAddress
	{
		bool operator()(const btManifoldAddress& a, const btManifoldAddress& b) const { return a.m_points < b.m_points; }
	};
	m_manifoldByAddress.quickSort(ByAddress());
}

btScalar btShockPropagationConstraintSolver::totalBefore(const btManifoldPoint* cp) const
{
	int lo = 0, hi = m_manifoldByAddress.size();  // last manifold whose points start at or before cp
	while (hi - lo > 1)
	{
		const int mid = (lo + hi) / 2;
		if (m_manifoldByAddress[mid].m_points <= cp) lo = mid;
		else hi = mid;
	}
	if (hi == 0) return btScalar(0);
	const btManifoldAddress& found = m_manifoldByAddress[lo];
	const std::ptrdiff_t j = cp - found.m_points;
	if (j < 0 || j >= MANIFOLD_CACHE_SIZE) return btScalar(0);
	return m_totalBefore[found.m_index * MANIFOLD_CACHE_SIZE + int(j)];
}

void btShockPropagationConstraintSolver::warmStartWeightPass(int numFreeBodies)
{
	// Each free body b must now also carry the impulse R_b handed down to it. Its lower contacts
	// (other end fixated or static) start from the layer pass's U_i; the previous step's layer
	// total T_i - G_i says how a resting body shares such a load among its points, so start them
	// at U_i + s_b w_i, w_i = max(0, T_i - G_i - U_i), with s_b <= 1 chosen so that the added
	// impulse E_b = sum w_i d_i does not exceed R_b: s_b = min(1, max(0, -R_b . E_b) / |E_b|^2).
	// A body that received nothing gets no warm start (a cache from before a role swap cannot
	// fling it). Only the free body moves; the lower end's share is withheld like the rest of
	// the pass's impulse (withholdReactions counts from U).
	m_layerSupport.resize(numFreeBodies);
	for (int b = 0; b < numFreeBodies; ++b) m_layerSupport[b].setZero();
	const int numRows = m_tmpSolverContactConstraintPool.size();
	m_weightWarmStart.resize(numRows);
	for (int i = 0; i < numRows; ++i)
	{
		const btSolverConstraint& row = m_tmpSolverContactConstraintPool[i];
		m_weightWarmStart[i] = btScalar(0);
		const bool freeA = row.m_solverBodyIdA < numFreeBodies;
		const bool freeB = row.m_solverBodyIdB < numFreeBodies;
		if (freeA == freeB) continue;  // a contact inside the layer
		const btManifoldPoint* cp = static_cast<const btManifoldPoint*>(row.m_originalContactPoint);
		const btScalar extra = totalBefore(cp) - cp->m_prevRHS - btScalar(row.m_appliedImpulse);
		if (!(extra > btScalar(0)) || !isFiniteScalar(extra)) continue;
		m_weightWarmStart[i] = extra;
		if (freeA) m_layerSupport[row.m_solverBodyIdA] += row.m_contactNormal1 * extra;
		else m_layerSupport[row.m_solverBodyIdB] += row.m_contactNormal2 * extra;
	}
	for (int i = 0; i < numRows; ++i)
	{
		if (m_weightWarmStart[i] == btScalar(0)) continue;
		btSolverConstraint& row = m_tmpSolverContactConstraintPool[i];
		const bool freeA = row.m_solverBodyIdA < numFreeBodies;
		const int b = freeA ? row.m_solverBodyIdA : row.m_solverBodyIdB;
		const btVector3& added = m_layerSupport[b];
		const btVector3& received = m_receivedLinear[m_layers.getFreeBody(m_currentLayer, b)];
		const btScalar scale = btMin(btScalar(1), btMax(btScalar(0), -received.dot(added)) / added.length2());
		const btScalar extra = scale * m_weightWarmStart[i];
		if (!(extra > btScalar(0))) continue;
		row.m_appliedImpulse = row.m_appliedImpulse + extra;
		btSolverBody& body = m_tmpSolverBodyPool[b];
		if (freeA) body.internalApplyImpulse(row.m_contactNormal1 * body.internalGetInvMass(), row.m_angularComponentA, extra);
		else body.internalApplyImpulse(row.m_contactNormal2 * body.internalGetInvMass(), row.m_angularComponentB, extra);
	}
}

void btShockPropagationConstraintSolver::withholdReactions()
{
	// Sum J_F^T lambda over the rows with a fixated end F into F's withheld impulse. The weight
	// pass's contact rows started at the layer pass's impulse, already withheld: count the change.
	const bool continued = m_pass == BT_PASS_WEIGHT;
	visitRows(m_tmpSolverContactConstraintPool, m_tmpSolverContactFrictionConstraintPool, m_tmpSolverContactRollingFrictionConstraintPool,
			  m_tmpSolverNonContactConstraintPool, [&](btSolverConstraint& row, btSolverRowKind kind) {
				  btScalar lambda = btScalar(row.m_appliedImpulse);
				  if (continued && kind == BT_ROW_CONTACT)
				  {
					  const btManifoldPoint* cp = static_cast<const btManifoldPoint*>(row.m_originalContactPoint);
					  lambda -= layerShare(*cp);
				  }
				  if (lambda == btScalar(0)) return;
				  const int nodeA = m_nodeOfSolverBody[row.m_solverBodyIdA];
				  const int nodeB = m_nodeOfSolverBody[row.m_solverBodyIdB];
				  if (nodeA >= 0)
				  {
					  m_withheldLinear[nodeA] += row.m_contactNormal1 * lambda;
					  m_withheldAngular[nodeA] += row.m_relpos1CrossNormal * lambda;
					  m_hasWithheld[nodeA] = 1;
				  }
				  if (nodeB >= 0)
				  {
					  m_withheldLinear[nodeB] += row.m_contactNormal2 * lambda;
					  m_withheldAngular[nodeB] += row.m_relpos2CrossNormal * lambda;
					  m_hasWithheld[nodeB] = 1;
				  }
			  });
}

btContactSolverInfo btShockPropagationConstraintSolver::makePassInfo(btPass pass, const btContactSolverInfo& info, btScalar timeStep) const
{
	btContactSolverInfo p = info;
	p.m_timeStep = timeStep;
	p.m_numIterations = pass == BT_PASS_GLOBAL ? m_settings.m_globalIterations : pass == BT_PASS_CORRECTION ? m_settings.m_correctionIterations : m_settings.m_layerIterations;
	p.m_erp2 = btScalar(0);  // D6: no Baumgarte in dynamics; correction() removes penetration
	// Joint error: Bullet asks a joint row for erp * error / timeStep. Positions advance once, over
	// the whole step, with the last pass's velocity (D3), so a pass of f dt must ask for the same
	// velocity as a stock step, erp * error / dt: scale erp by the pass's share of the step. Else
	// the joint removes error / f of its error per step (2x at f = 0.5; past 1, and unstable, at
	// f > 0.8), and a light jointed body is thrown. Joints with their own stop ERP (6-dof limits)
	// do not read m_erp and keep the sub-step's bias.
	if (pass != BT_PASS_CORRECTION && info.m_timeStep > btScalar(0))
	{
		p.m_erp = info.m_erp * btMin(btScalar(1), timeStep / info.m_timeStep);
	}
	// The split-impulse slot of Bullet's iterations runs our correction() and its write-back
	// moves positions by push * timeStep with full rotation.
	p.m_splitImpulse = pass != BT_PASS_GLOBAL && pass != BT_PASS_WEIGHT;
	p.m_splitImpulseTurnErp = btScalar(1);
	if (m_settings.m_twoFrictionDirections)
	{
		p.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
	}
	if (pass == BT_PASS_WEIGHT)
	{
		// A fixed number of sweeps: stopping at a small per-sweep change (Bullet's residual
		// threshold) left towers and walls unconverged and falling (measured, README D13).
		p.m_numIterations = m_settings.m_weightIterations;
	}
	if (pass == BT_PASS_CORRECTION || pass == BT_PASS_WEIGHT)
	{
		p.m_solverMode &= ~SOLVER_USE_WARMSTARTING;  // the weight pass continues from the layer pass (prepareWeightPass)
	}
	return p;
}

void btShockPropagationConstraintSolver::prepareWarmStart(btPass pass, btPersistentManifold** manifolds, int numManifolds, btScalar timeStep)
{
	// D5, per point between steps: m_appliedImpulse = total T, m_prevRHS = global share G.
	// Bullet's setup warm-starts from m_appliedImpulse, so put this pass's own share there.
	const btScalar f = m_settings.m_weighting;
	for (int i = 0; i < numManifolds; ++i)
	{
		btPersistentManifold* m = manifolds[i];
		// Role swaps: a layer impulse L cached while the other body was the fixated one (a heavy
		// body resting on a light one) would hit the light body when their layers swap and fling
		// it (hostile worlds with 1e-3 to 1e6 kg bodies, tests/robustness). So a layer warm start
		// is at most what this step's global share G carries in a converged resting stack,
		// L <= G (1 - f) / f, or kWarmStartWeights times the lighter body's weight impulse
		// m g dt, whichever is larger; a single solve likewise T <= max(G / f, same bound).
		// Equal masses (every registry scene) stay far below the second bound.
		const btScalar lightWeightImpulse = kWarmStartWeights * lighterWeight(m) * timeStep;
		for (int j = 0; j < m->getNumContacts(); ++j)
		{
			btManifoldPoint& cp = m->getContactPoint(j);
			const btScalar total = cp.m_appliedImpulse;
			const btScalar global = cp.m_prevRHS;
			if (m_settings.m_weightFeeling)
			{
				prepareWeightFeelingWarmStart(pass, cp, lightWeightImpulse);
			}
			else if (pass == BT_PASS_SINGLE)
			{
				// After a layered step; a single solve stores G = f T, so single after single keeps T.
				if (f > btScalar(0)) cp.m_appliedImpulse = btMin(total, btMax(global / f, lightWeightImpulse));
			}
			else if (pass == BT_PASS_GLOBAL)
			{
				cp.m_appliedImpulse = global;                           // warm start G
				cp.m_prevRHS = btMax(btScalar(0), total - global);      // keep L for the layer pass
			}
			else if (pass == BT_PASS_LAYER)
			{
				if (m_globalPassRan)
				{
					cp.m_appliedImpulse = btMin(global, btMax(total * (btScalar(1) - f) / f, lightWeightImpulse));  // L, clamped
					cp.m_prevRHS = total;  // this step's G
				}
				else
				{
					cp.m_appliedImpulse = btMax(btScalar(0), total - global);
					cp.m_prevRHS = btScalar(0);
				}
			}
		}
	}
}

void btShockPropagationConstraintSolver::prepareWeightFeelingWarmStart(btPass pass, btManifoldPoint& cp, btScalar lightWeightImpulse)
{
	// D5 with weight feeling (D13), per point between steps: m_appliedImpulse = total T,
	// m_prevRHS = the layer pass's share U (what the free body needed before the weight pass).
	// The global pass warm-starts from f T (the share a converged global pass carries at rest,
	// now that T is the whole weight), the layer pass from U (clamped against role swaps as
	// without weight feeling); the weight pass continues from U (prepareWeightPass).
	const btScalar f = m_settings.m_weighting;
	if (pass == BT_PASS_GLOBAL)
	{
		cp.m_appliedImpulse = f * cp.m_appliedImpulse;  // m_prevRHS keeps U for the layer pass
	}
	else if (pass == BT_PASS_LAYER)
	{
		const btScalar up = cp.m_prevRHS;
		if (m_globalPassRan)
		{
			const btScalar global = cp.m_appliedImpulse;  // this step's G
			cp.m_appliedImpulse = btMin(up, btMax(global * (btScalar(1) - f) / f, lightWeightImpulse));
			cp.m_prevRHS = global;
		}
		else
		{
			cp.m_appliedImpulse = up;
			cp.m_prevRHS = btScalar(0);
		}
	}
	// BT_PASS_SINGLE: warm start from T, every body free.
}

void btShockPropagationConstraintSolver::solvePass(btPass pass, btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds,
												   int numManifolds, btTypedConstraint** constraints, int numConstraints,
												   const btContactSolverInfo& info, btScalar timeStep, btIDebugDraw* debugDrawer)
{
	m_pass = pass;
	const btContactSolverInfo passInfo = makePassInfo(pass, info, timeStep);
	if (pass != BT_PASS_CORRECTION && pass != BT_PASS_WEIGHT)
	{
		prepareWarmStart(pass, manifolds, numManifolds, timeStep);
	}
	solveGroupCacheFriendlySetup(bodies, numBodies, manifolds, numManifolds, constraints, numConstraints, passInfo, debugDrawer);
	if (pass == BT_PASS_WEIGHT)
	{
		prepareWeightPass(numBodies, passInfo);
	}
	if (pass == BT_PASS_LAYER || pass == BT_PASS_WEIGHT || pass == BT_PASS_CORRECTION)
	{
		fixateLowerBodies(numBodies, passInfo);  // no-op when every converted body is free
	}
	if (m_weightFeelingActive && (pass == BT_PASS_LAYER || pass == BT_PASS_WEIGHT))
	{
		mapFixatedSolverBodies(m_currentLayer);
	}
	if (pass == BT_PASS_WEIGHT)
	{
		warmStartWeightPass(numBodies);
	}
	if (pass == BT_PASS_CORRECTION)
	{
		solveGroupCacheFriendlySplitImpulseIterations(bodies, numBodies, manifolds, numManifolds, constraints, numConstraints, passInfo, debugDrawer);
		writeCorrectedTransforms(passInfo.m_timeStep);
	}
	else
	{
		solveGroupCacheFriendlyIterations(bodies, numBodies, manifolds, numManifolds, constraints, numConstraints, passInfo, debugDrawer);
		solveGroupCacheFriendlyFinish(bodies, numBodies, passInfo);
	}
	for (int i = 0; i < m_fixatedBodies.size(); ++i)
	{
		m_fixatedBodies[i]->setCompanionId(-1);
	}
	m_fixatedBodies.resize(0);
}

void btShockPropagationConstraintSolver::collectLayer(int layer, btAlignedObjectArray<char>* manifoldInLayer)
{
	m_layerBodies.resize(0);
	m_layerManifolds.resize(0);
	m_layerConstraints.resize(0);
	for (int i = 0; i < m_layers.getNumFreeBodies(layer); ++i)
	{
		m_layerBodies.push_back(m_bodies[m_layers.getFreeBody(layer, i)]);
	}
	for (int i = 0; i < m_layers.getNumLayerEdges(layer); ++i)
	{
		const int source = m_graph.getEdge(m_layers.getLayerEdge(layer, i)).m_source;
		if (source >= 0)
		{
			m_layerManifolds.push_back(m_manifolds[source]);
			if (manifoldInLayer) (*manifoldInLayer)[source] = 1;
		}
		else
		{
			m_layerConstraints.push_back(m_constraints[-source - 1]);
		}
	}
}

void btShockPropagationConstraintSolver::fixateLowerBodies(int numFreeBodies, const btContactSolverInfo& info)
{
	// Solver bodies 0..numFreeBodies-1 are this layer's free bodies (convertBodies creates them
	// first). Every other dynamic solver body was pulled in by a layer edge: it is a lower body
	// (height k) and is fixated for this layer.
	const int numSolverBodies = m_tmpSolverBodyPool.size();
	m_fixatedRigidBody.resize(numSolverBodies);
	bool any = false;
	for (int id = 0; id < numSolverBodies; ++id)
	{
		const btRigidBody* rb = m_tmpSolverBodyPool[id].m_originalBody;
		const bool fixate = id >= numFreeBodies && rb && rb->getInvMass() != btScalar(0);
		m_fixatedRigidBody[id] = fixate ? rb : 0;
		any = any || fixate;
	}
	if (!any)
	{
		return;
	}
	btLayerFixationParams params;
	params.m_mode = m_settings.m_fixationMode;
	params.m_sor = info.m_sor;
	params.m_jointDamping = info.m_damping;
	params.m_inelasticFixation = m_settings.m_inelasticFixation;

	visitRows(m_tmpSolverContactConstraintPool, m_tmpSolverContactFrictionConstraintPool, m_tmpSolverContactRollingFrictionConstraintPool,
			  m_tmpSolverNonContactConstraintPool, [&](btSolverConstraint& row, btSolverRowKind kind) {
				  const bool fixA = m_fixatedRigidBody[row.m_solverBodyIdA] != 0;
				  const bool fixB = m_fixatedRigidBody[row.m_solverBodyIdB] != 0;
				  if (fixA || fixB)
				  {
					  btFixateSolverRow(row, kind, m_tmpSolverBodyPool[row.m_solverBodyIdA], m_tmpSolverBodyPool[row.m_solverBodyIdB], fixA, fixB, params);
				  }
			  });
	for (int id = 0; id < numSolverBodies; ++id)
	{
		if (m_fixatedRigidBody[id])
		{
			// Keep the companion id until the solve ends: Bullet looks joints' bodies up by it.
			m_fixatedBodies.push_back(btFixateSolverBody(m_tmpSolverBodyPool[id], m_settings.m_fixationMode));
		}
	}
}

void btShockPropagationConstraintSolver::solveGroupCacheFriendlySplitImpulseIterations(btCollisionObject** /*bodies*/, int /*numBodies*/,
																						 btPersistentManifold** /*manifolds*/, int /*numManifolds*/,
																						 btTypedConstraint** /*constraints*/, int /*numConstraints*/,
																						 const btContactSolverInfo& info, btIDebugDraw* /*debugDrawer*/)
{
	// correction() (algorithm.md 1.3): normal rows only, A x - d >= 0 _|_ x >= 0 with
	// d_i = fraction * max(0, -distance_i - slop), dq = W J^T x moves positions only. Bullet's
	// write-back integrates push * timeStep, hence the division by timeStep here.
	if (m_pass == BT_PASS_GLOBAL || m_pass == BT_PASS_WEIGHT || m_settings.m_correctionIterations <= 0)
	{
		return;
	}
	BT_PROFILE("correction");
	const btScalar invTimeStep = btScalar(1) / info.m_timeStep;
	const int numRows = m_tmpSolverContactConstraintPool.size();
	for (int i = 0; i < numRows; ++i)
	{
		btSolverConstraint& c = m_tmpSolverContactConstraintPool[i];
		const btManifoldPoint* cp = static_cast<const btManifoldPoint*>(c.m_originalContactPoint);
		const btScalar depth = -cp->getDistance() - m_settings.m_correctionSlop;
		c.m_rhsPenetration = depth > btScalar(0) ? m_settings.m_correctionFraction * depth * invTimeStep * c.m_jacDiagABInv : btScalar(0);
		c.m_appliedPushImpulse = btScalar(0);
	}
	for (int iteration = 0; iteration < m_settings.m_correctionIterations; ++iteration)
	{
		for (int i = 0; i < numRows; ++i)
		{
			btSolverConstraint& c = m_tmpSolverContactConstraintPool[i];
			resolvePositionRow(m_tmpSolverBodyPool[c.m_solverBodyIdA], m_tmpSolverBodyPool[c.m_solverBodyIdB], c);
		}
	}
	if (m_pass == BT_PASS_CORRECTION && m_settings.m_correctionStopsApproach)
	{
		stopApproachAtPenetratingContacts();
	}
}

btScalar btShockPropagationConstraintSolver::approachVelocity(const btSolverConstraint& c, const btSolverBody& a, const btSolverBody& b) const
{
	// J u of each end; a fixated end moves as the layer passes let it move (D1: its rotation is
	// ignored unless the full velocity is kept; at rest in zero-velocity mode).
	const btShockPropagationFixationMode mode = m_settings.m_fixationMode;
	const bool fixA = c.m_solverBodyIdA < m_fixatedRigidBody.size() && m_fixatedRigidBody[c.m_solverBodyIdA];
	const bool fixB = c.m_solverBodyIdB < m_fixatedRigidBody.size() && m_fixatedRigidBody[c.m_solverBodyIdB];
	auto side = [mode](bool fixated, const btSolverBody& body, const btVector3& linear, const btVector3& angular) {
		return fixated ? btFixatedEndVelocity(body, linear, angular, mode) : linear.dot(body.m_linearVelocity) + angular.dot(body.m_angularVelocity);
	};
	btScalar uA = side(fixA, a, c.m_contactNormal1, c.m_relpos1CrossNormal);
	btScalar uB = side(fixB, b, c.m_contactNormal2, c.m_relpos2CrossNormal);
	if (m_settings.m_inelasticFixation && fixA != fixB)
	{
		// D14: the fixated end pushes at most at the inelastic common velocity.
		const btRigidBody* fixed = fixA ? m_fixatedRigidBody[c.m_solverBodyIdA] : m_fixatedRigidBody[c.m_solverBodyIdB];
		const btVector3& linear = fixA ? c.m_contactNormal1 : c.m_contactNormal2;
		const btVector3& angular = fixA ? c.m_relpos1CrossNormal : c.m_relpos2CrossNormal;
		const btScalar wFixed = fixed->getInvMass() * linear.length2() + angular.dot(fixed->getInvInertiaTensorWorld() * angular);
		// The free end's J W J^T: the row's effective mass is sor / (w_free + cfm); cfm is 0 or tiny here.
		const btScalar wFree = c.m_jacDiagABInv > btScalar(0) ? btScalar(1) / c.m_jacDiagABInv : btScalar(0);
		btScalar& fixedU = fixA ? uA : uB;
		const btScalar freeU = fixA ? uB : uA;
		fixedU = -btInelasticApproach(-fixedU, freeU, wFixed, wFree);
	}
	return uA + uB;
}

void btShockPropagationConstraintSolver::stopApproachAtPenetratingContacts()
{
	// D11: at every contact that penetrates after the step, take out the velocity into it
	// (inelastic, normal rows only): rel_vel_i + (J W J^T lambda)_i >= 0 _|_ lambda_i >= 0.
	// The position correction alone can leave a body touching at zero distance, where Bullet's
	// box-box test reports no contact: the next dynamics phase would not see the contact and the
	// velocity into it would grow by g dt every step while the correction keeps teleporting
	// the body back (measured: dense_random, friction_ramp). Velocities exclude this pass's gravity.
	const int numRows = m_tmpSolverContactConstraintPool.size();
	bool anyMissed = false;
	for (int i = 0; i < numRows; ++i)
	{
		btSolverConstraint& c = m_tmpSolverContactConstraintPool[i];
		const btManifoldPoint* cp = static_cast<const btManifoldPoint*>(c.m_originalContactPoint);
		const btSolverBody& a = m_tmpSolverBodyPool[c.m_solverBodyIdA];
		const btSolverBody& b = m_tmpSolverBodyPool[c.m_solverBodyIdB];
		const btScalar relativeVelocity = approachVelocity(c, a, b);
		const bool penetrating = cp->getDistance() < btScalar(0);
		const bool missed = relativeVelocity < -m_settings.m_correctionApproachSpeed;
		c.m_rhs = (penetrating && missed) ? -relativeVelocity * c.m_jacDiagABInv : btScalar(0);
		c.m_appliedImpulse = btScalar(0);
		anyMissed = anyMissed || c.m_rhs > btScalar(0);
	}
	if (!anyMissed)
	{
		return;  // resting scenes: nothing to project, skip the sweeps
	}
	for (int iteration = 0; iteration < m_settings.m_correctionIterations; ++iteration)
	{
		for (int i = 0; i < numRows; ++i)
		{
			btSolverConstraint& c = m_tmpSolverContactConstraintPool[i];
			btSolverBody& a = m_tmpSolverBodyPool[c.m_solverBodyIdA];
			btSolverBody& b = m_tmpSolverBodyPool[c.m_solverBodyIdB];
			btScalar delta = c.m_rhs;
			delta -= (c.m_contactNormal1.dot(a.internalGetDeltaLinearVelocity()) + c.m_relpos1CrossNormal.dot(a.internalGetDeltaAngularVelocity())) * c.m_jacDiagABInv;
			delta -= (c.m_contactNormal2.dot(b.internalGetDeltaLinearVelocity()) + c.m_relpos2CrossNormal.dot(b.internalGetDeltaAngularVelocity())) * c.m_jacDiagABInv;
			const btScalar sum = btScalar(c.m_appliedImpulse) + delta;
			if (sum < btScalar(0))
			{
				delta = -btScalar(c.m_appliedImpulse);
				c.m_appliedImpulse = btScalar(0);
			}
			else
			{
				c.m_appliedImpulse = sum;
			}
			a.internalApplyImpulse(c.m_contactNormal1 * a.internalGetInvMass(), c.m_angularComponentA, delta);
			b.internalApplyImpulse(c.m_contactNormal2 * b.internalGetInvMass(), c.m_angularComponentB, delta);
		}
	}
}

btScalar btShockPropagationConstraintSolver::solveSingleIteration(int iteration, btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds,
															   int numManifolds, btTypedConstraint** constraints, int numConstraints,
															   const btContactSolverInfo& info, btIDebugDraw* debugDrawer)
{
	if (m_pass == BT_PASS_WEIGHT) m_stats.m_numWeightSweeps += 1;
	return btSequentialImpulseConstraintSolver::solveSingleIteration(iteration, bodies, numBodies, manifolds, numManifolds, constraints, numConstraints, info, debugDrawer);
}

btScalar btShockPropagationConstraintSolver::solveGroupCacheFriendlyFinish(btCollisionObject** bodies, int numBodies, const btContactSolverInfo& info)
{
	const bool rejected = m_pass == BT_PASS_WEIGHT && !weightPassAccepted(numBodies);
	if (m_weightFeelingActive && (m_pass == BT_PASS_LAYER || m_pass == BT_PASS_WEIGHT) && !rejected)
	{
		withholdReactions();  // D13: before the contact caches below are overwritten
	}
	if (rejected)
	{
		// D13 guard: the layer keeps what the layer pass gave it; nothing more is handed down.
		m_stats.m_numWeightRejections += 1;
		for (int i = 0; i < m_tmpSolverContactConstraintPool.size(); ++i)
		{
			btManifoldPoint* cp = static_cast<btManifoldPoint*>(m_tmpSolverContactConstraintPool[i].m_originalContactPoint);
			cp->m_prevRHS = layerShare(*cp);  // U
		}
		btContactSolverInfo bulletInfo = info;
		bulletInfo.m_solverMode &= ~SOLVER_USE_WARMSTARTING;
		btSequentialImpulseConstraintSolver::solveGroupCacheFriendlyFinish(bodies, numBodies, bulletInfo);
		for (int i = 0; i < numBodies && i < m_layerVelocityBefore.size(); ++i)
		{
			btRigidBody* rb = btRigidBody::upcast(bodies[i]);
			if (!rb) continue;
			rb->setLinearVelocity(m_layerVelocityBefore[i].m_linear);
			rb->setAngularVelocity(m_layerVelocityBefore[i].m_angular);
		}
		return btScalar(0);
	}
	// D5: per-pass caches and the step total (see prepareWarmStart).
	const bool twoFrictionRows = (info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) != 0;
	for (int i = 0; i < m_tmpSolverContactConstraintPool.size(); ++i)
	{
		const btSolverConstraint& row = m_tmpSolverContactConstraintPool[i];
		btManifoldPoint* cp = static_cast<btManifoldPoint*>(row.m_originalContactPoint);
		const btScalar normal = row.m_appliedImpulse;
		const btScalar lateral1 = m_tmpSolverContactFrictionConstraintPool[row.m_frictionIndex].m_appliedImpulse;
		const btScalar lateral2 = twoFrictionRows ? btScalar(m_tmpSolverContactFrictionConstraintPool[row.m_frictionIndex + 1].m_appliedImpulse) : btScalar(0);
		if (m_pass == BT_PASS_WEIGHT)
		{
			const btScalar global = cp->m_prevRHS;
			const btScalar up = layerShare(*cp);  // where this pass started
			cp->m_appliedImpulse = normal + global;  // total = layer (continued) + global share
			cp->m_prevRHS = up;                      // U, the layer pass's warm start next step
			cp->m_appliedImpulseLateral1 += lateral1;       // friction rows solved the change only
			cp->m_appliedImpulseLateral2 += lateral2;
		}
		else if (m_pass == BT_PASS_LAYER)
		{
			cp->m_appliedImpulse = normal + cp->m_prevRHS;  // total = layer + global share
			cp->m_appliedImpulseLateral1 = lateral1 + (m_globalPassRan ? cp->m_appliedImpulseLateral1 : btScalar(0));
			cp->m_appliedImpulseLateral2 = lateral2 + (m_globalPassRan ? cp->m_appliedImpulseLateral2 : btScalar(0));
		}
		else
		{
			cp->m_appliedImpulse = normal;
			cp->m_appliedImpulseLateral1 = lateral1;
			cp->m_appliedImpulseLateral2 = lateral2;
			if (m_pass == BT_PASS_SINGLE)
			{
				// The share a global pass would carry; with weight feeling the layer pass's own
				// share U, unknown after a single solve.
				cp->m_prevRHS = m_settings.m_weightFeeling ? btScalar(0) : m_settings.m_weighting * normal;
			}
		}
	}
	btContactSolverInfo bulletInfo = info;
	bulletInfo.m_solverMode &= ~SOLVER_USE_WARMSTARTING;  // contacts are written above
	return btSequentialImpulseConstraintSolver::solveGroupCacheFriendlyFinish(bodies, numBodies, bulletInfo);
}

void btShockPropagationConstraintSolver::solveCorrection(const btContactSolverInfo& info, btIDebugDraw* debugDrawer)
{
	// The second correction after CD(t + dt): positions only.
	btClock clock;
	btCollisionObject** bodies = m_bodies.size() ? &m_bodies[0] : 0;
	btPersistentManifold** manifolds = m_manifolds.size() ? &m_manifolds[0] : 0;
	int numLayers = 1;
	if (m_settings.m_layeredSecondCorrection)
	{
		buildGraph();
		numLayers = m_layers.getNumLayers();
	}
	if (numLayers <= 1)
	{
		// Paper and OpenTissue: one global correction, every dynamic body free.
		solvePass(BT_PASS_CORRECTION, bodies, m_bodies.size(), manifolds, m_manifolds.size(), 0, 0, info, info.m_timeStep, debugDrawer);
	}
	else
	{
		// Shock-propagated: bottom-up, each layer's lower bodies fixated, fresh depths of CD(t + dt).
		for (int k = 0; k < numLayers; ++k)
		{
			collectLayer(k, 0);  // joints take no part in the correction
			solvePass(BT_PASS_CORRECTION, m_layerBodies.size() ? &m_layerBodies[0] : 0, m_layerBodies.size(),
					  m_layerManifolds.size() ? &m_layerManifolds[0] : 0, m_layerManifolds.size(), 0, 0, info, info.m_timeStep, debugDrawer);
		}
	}
	m_stats.m_timeCorrectionMs += millisecondsSince(clock);
}

void btShockPropagationConstraintSolver::writeCorrectedTransforms(btScalar timeStep)
{
	// Positions, and the velocity taken out of penetrating contacts (D11); contact impulses and
	// forces stay as the dynamics phase left them.
	for (int i = 0; i < m_tmpSolverBodyPool.size(); ++i)
	{
		btSolverBody& sb = m_tmpSolverBodyPool[i];
		btRigidBody* rb = sb.m_originalBody;
		if (!rb) continue;
		if (!sb.internalGetDeltaLinearVelocity().isZero() || !sb.internalGetDeltaAngularVelocity().isZero())
		{
			rb->setLinearVelocity(rb->getLinearVelocity() + sb.internalGetDeltaLinearVelocity());
			rb->setAngularVelocity(rb->getAngularVelocity() + sb.internalGetDeltaAngularVelocity());
		}
		if (!sb.internalGetPushVelocity().isZero() || !sb.internalGetTurnVelocity().isZero())
		{
			btTransform corrected;
			btTransformUtil::integrateTransform(sb.m_worldTransform, sb.internalGetPushVelocity(), sb.internalGetTurnVelocity(), timeStep, corrected);
			rb->setWorldTransform(corrected);
			rb->setInterpolationWorldTransform(corrected);
		}
		rb->setCompanionId(-1);
	}
	m_tmpSolverContactConstraintPool.resizeNoInitialize(0);
	m_tmpSolverNonContactConstraintPool.resizeNoInitialize(0);
	m_tmpSolverContactFrictionConstraintPool.resizeNoInitialize(0);
	m_tmpSolverContactRollingFrictionConstraintPool.resizeNoInitialize(0);
	m_tmpSolverBodyPool.resizeNoInitialize(0);
}
