#include "harness/ContactRecorder.h"

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletShockPropagation/btShockPropagationConstraintSolver.h>

namespace harness
{
namespace
{
/// World direction of a row for body A (Bullet leaves the static side's half of a row zero).
btVector3 rowDirection(const btSolverConstraint& row)
{
	return row.m_contactNormal1.length2() > btScalar(0) ? row.m_contactNormal1 : -row.m_contactNormal2;
}

void copy3(const btVector3& v, double* out)
{
	out[0] = v.x();
	out[1] = v.y();
	out[2] = v.z();
}
}  // namespace

/// Bullet's own row setup, run on the side: exposes the pools it fills.
class ContactRecorder::RowBuilder : public btSequentialImpulseConstraintSolver
{
public:
	void build(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds, int numManifolds, const btContactSolverInfo& info)
	{
		btContactSolverInfo rowsInfo = info;
		rowsInfo.m_solverMode = SOLVER_USE_2_FRICTION_DIRECTIONS;  // no warm start: rows only
		solveGroupCacheFriendlySetup(bodies, numBodies, manifolds, numManifolds, nullptr, 0, rowsInfo, nullptr);
	}
	/// Undo what setup left on the bodies (companion ids) and drop the rows.
	void clear()
	{
		for (int i = 0; i < m_tmpSolverBodyPool.size(); ++i)
			if (m_tmpSolverBodyPool[i].m_originalBody) m_tmpSolverBodyPool[i].m_originalBody->setCompanionId(-1);
		m_tmpSolverBodyPool.resizeNoInitialize(0);
		m_tmpSolverContactConstraintPool.resizeNoInitialize(0);
		m_tmpSolverContactFrictionConstraintPool.resizeNoInitialize(0);
		m_tmpSolverContactRollingFrictionConstraintPool.resizeNoInitialize(0);
		m_tmpSolverNonContactConstraintPool.resizeNoInitialize(0);
	}
	const btAlignedObjectArray<btSolverBody>& bodyPool() const { return m_tmpSolverBodyPool; }
	const btConstraintArray& contactRows() const { return m_tmpSolverContactConstraintPool; }
	const btConstraintArray& frictionRows() const { return m_tmpSolverContactFrictionConstraintPool; }
};

ContactRecorder::ContactRecorder() : m_builder(new RowBuilder)
{
}

ContactRecorder::~ContactRecorder() = default;

void ContactRecorder::arm()
{
	clear();
	m_state = State::Waiting;
}

void ContactRecorder::beginStep()
{
	if (m_state == State::Waiting)
		m_state = State::Capturing;
	else if (m_state == State::Capturing)
		m_state = State::Done;
}

void ContactRecorder::clear()
{
	m_problem = ContactProblem();
	m_bodyIndex.clear();
	m_applied.clear();
	m_rowPoint.clear();
	m_rowDirection.clear();
}

ContactProblem ContactRecorder::take()
{
	m_state = State::Idle;
	ContactProblem out;
	std::swap(out, m_problem);
	clear();
	return out;
}

void ContactRecorder::captureGroup(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds, int numManifolds,
								   const btContactSolverInfo& info)
{
	// Setup overwrites the points' friction directions; put them back so the solver under test
	// starts from exactly what it would have seen.
	std::vector<std::pair<btVector3, btVector3>> directions;
	for (int i = 0; i < numManifolds; ++i)
		for (int j = 0; j < manifolds[i]->getNumContacts(); ++j)
		{
			const btManifoldPoint& cp = manifolds[i]->getContactPoint(j);
			directions.push_back({cp.m_lateralFrictionDir1, cp.m_lateralFrictionDir2});
		}
	m_builder->build(bodies, numBodies, manifolds, numManifolds, info);
	size_t k = 0;
	for (int i = 0; i < numManifolds; ++i)
		for (int j = 0; j < manifolds[i]->getNumContacts(); ++j, ++k)
		{
			btManifoldPoint& cp = manifolds[i]->getContactPoint(j);
			cp.m_lateralFrictionDir1 = directions[k].first;
			cp.m_lateralFrictionDir2 = directions[k].second;
		}

	m_problem.timeStep = info.m_timeStep;
	const btAlignedObjectArray<btSolverBody>& pool = m_builder->bodyPool();
	// Solver body -> problem body (-1: static or kinematic), and each solver body's free velocity.
	std::vector<int> index(pool.size(), -1);
	std::vector<btVector3> linear(pool.size()), angular(pool.size());
	for (int i = 0; i < pool.size(); ++i)
	{
		const btSolverBody& sb = pool[i];
		linear[i] = sb.m_linearVelocity + sb.m_externalForceImpulse;
		angular[i] = sb.m_angularVelocity + sb.m_externalTorqueImpulse;
		const btRigidBody* rb = sb.m_originalBody;
		if (!rb || rb->getInvMass() == btScalar(0)) continue;
		auto found = m_bodyIndex.find(rb);
		if (found == m_bodyIndex.end())
		{
			ContactProblem::Body body;
			body.invMass = rb->getInvMass();
			const btMatrix3x3& inertia = rb->getInvInertiaTensorWorld();
			for (int r = 0; r < 3; ++r)
				for (int c = 0; c < 3; ++c) body.invInertia[3 * r + c] = inertia[r][c];
			found = m_bodyIndex.emplace(rb, int(m_problem.bodies.size())).first;
			m_problem.bodies.push_back(body);
		}
		index[i] = found->second;
	}

	auto addRow = [&](const btSolverConstraint& c, ContactProblem::RowKind kind, int normalRow) {
		ContactProblem::Row row;
		row.kind = kind;
		row.bodyA = index[c.m_solverBodyIdA];
		row.bodyB = index[c.m_solverBodyIdB];
		// The full Jacobian of the row (Bullet zeroes the half of a static side; its velocity is 0).
		const btVector3 n = rowDirection(c);
		copy3(n, row.jacobianA);
		copy3(c.m_relpos1CrossNormal, row.jacobianA + 3);
		copy3(-n, row.jacobianB);
		copy3(c.m_relpos2CrossNormal, row.jacobianB + 3);
		double b = n.dot(linear[c.m_solverBodyIdA]) + c.m_relpos1CrossNormal.dot(angular[c.m_solverBodyIdA]);
		b += (-n).dot(linear[c.m_solverBodyIdB]) + c.m_relpos2CrossNormal.dot(angular[c.m_solverBodyIdB]);
		const btManifoldPoint* cp = static_cast<const btManifoldPoint*>(c.m_originalContactPoint);
		if (kind == ContactProblem::kNormal && cp->getDistance() > btScalar(0)) b += cp->getDistance() / info.m_timeStep;
		row.b = b;
		row.normalRow = normalRow;
		row.mu = kind == ContactProblem::kFriction ? c.m_friction : 0;
		row.objectA = pool[c.m_solverBodyIdA].m_originalBody;
		row.objectB = pool[c.m_solverBodyIdB].m_originalBody;
		m_problem.rows.push_back(row);
		m_rowPoint.push_back(cp);
		m_rowDirection.push_back(n);
	};
	m_firstRowOfGroup = m_problem.rows.size();
	const btConstraintArray& contacts = m_builder->contactRows();
	const btConstraintArray& friction = m_builder->frictionRows();
	for (int i = 0; i < contacts.size(); ++i)
	{
		const btSolverConstraint& c = contacts[i];
		const int normalRow = int(m_problem.rows.size());
		addRow(c, ContactProblem::kNormal, -1);
		addRow(friction[c.m_frictionIndex], ContactProblem::kFriction, normalRow);
		addRow(friction[c.m_frictionIndex + 1], ContactProblem::kFriction, normalRow);
	}
	m_builder->clear();
}

void ContactRecorder::recordPass(const btConstraintArray& contactRows, const btConstraintArray& frictionRows, bool twoFrictionRows)
{
	for (int i = 0; i < contactRows.size(); ++i)
	{
		const btSolverConstraint& c = contactRows[i];
		Applied& applied = m_applied[static_cast<const btManifoldPoint*>(c.m_originalContactPoint)];
		applied.normal += c.m_appliedImpulse;
		if (c.m_frictionIndex < 0 || c.m_frictionIndex >= frictionRows.size()) continue;
		const btSolverConstraint& f1 = frictionRows[c.m_frictionIndex];
		applied.tangent += rowDirection(f1) * f1.m_appliedImpulse;
		if (twoFrictionRows && c.m_frictionIndex + 1 < frictionRows.size())
		{
			const btSolverConstraint& f2 = frictionRows[c.m_frictionIndex + 1];
			applied.tangent += rowDirection(f2) * f2.m_appliedImpulse;
		}
	}
}

void ContactRecorder::finishGroup()
{
	for (size_t r = m_firstRowOfGroup; r < m_problem.rows.size(); ++r)
	{
		ContactProblem::Row& row = m_problem.rows[r];
		const auto found = m_applied.find(m_rowPoint[r]);
		if (found == m_applied.end()) continue;
		row.solverImpulse = row.kind == ContactProblem::kNormal ? found->second.normal : double(found->second.tangent.dot(m_rowDirection[r]));
	}
	m_firstRowOfGroup = m_problem.rows.size();
}
}  // namespace harness
