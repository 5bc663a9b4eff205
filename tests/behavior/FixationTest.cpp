// Fixation is an infinite-mass override of the rows Bullet built: the effective mass of a row
// between a free body and a fixated one is the free body's alone, and the fixated btRigidBody is
// never modified.
#include "Fixture.h"

#include <BulletShockPropagation/btShockPropagationCommon.h>

#include <gtest/gtest.h>

namespace
{
struct CapturedRow
{
	const btRigidBody* freeBody;
	btVector3 contactPoint;  // world, on the free body
	btVector3 normal;        // world, unit
	btScalar effectiveMass;  // m_jacDiagABInv
};

/// Records, during each layer solve, the contact rows that have one detached (fixated) side.
class RowRecordingSolver : public btShockPropagationConstraintSolver
{
public:
	std::vector<CapturedRow> rows;

protected:
	btScalar solveGroupCacheFriendlyIterations(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds, int numManifolds,
											   btTypedConstraint** constraints, int numConstraints, const btContactSolverInfo& info,
											   btIDebugDraw* debugDrawer) override
	{
		for (int i = 0; i < m_tmpSolverContactConstraintPool.size(); ++i)
		{
			const btSolverConstraint& c = m_tmpSolverContactConstraintPool[i];
			const btSolverBody& a = m_tmpSolverBodyPool[c.m_solverBodyIdA];
			const btSolverBody& b = m_tmpSolverBodyPool[c.m_solverBodyIdB];
			const bool aFixated = !a.m_originalBody && c.m_solverBodyIdA != m_fixedBodyId;
			const bool bFixated = !b.m_originalBody && c.m_solverBodyIdB != m_fixedBodyId;
			if (aFixated == bFixated) continue;
			const btManifoldPoint* cp = static_cast<const btManifoldPoint*>(c.m_originalContactPoint);
			CapturedRow row;
			row.freeBody = aFixated ? b.m_originalBody : a.m_originalBody;
			row.contactPoint = aFixated ? cp->getPositionWorldOnB() : cp->getPositionWorldOnA();
			row.normal = cp->m_normalWorldOnB;
			row.effectiveMass = c.m_jacDiagABInv;
			rows.push_back(row);
		}
		return btShockPropagationConstraintSolver::solveGroupCacheFriendlyIterations(bodies, numBodies, manifolds, numManifolds, constraints,
																					  numConstraints, info, debugDrawer);
	}
};

/// 1 / (J W J^T) of a contact row on one body: 1 / (1/m + (r x n) . I^-1 (r x n)).
btScalar handEffectiveMass(const btRigidBody& body, const btVector3& point, const btVector3& normal)
{
	const btVector3 r = point - body.getCenterOfMassPosition();
	const btVector3 rxn = r.cross(normal);
	return btScalar(1) / (body.getInvMass() + rxn.dot(body.getInvInertiaTensorWorld() * rxn));
}
}  // namespace

TEST(BodyFixation, RowEffectiveMassIsTheFreeBodysAloneByHandComputation)
{
	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher(&configuration);
	btDbvtBroadphase broadphase;
	RowRecordingSolver solver;
	btShockPropagationDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
	world.setGravity(btVector3(0, btScalar(-9.81), 0));
	// Three boxes: the middle one is fixated under the top one in layer 1; a row that also counted
	// the middle box's inverse mass and inertia would be far from the hand value.
	std::unique_ptr<scenes::SceneContent> scene = scenes::createScene(world, "tower", {{"n", 3}});
	btRigidBody* top = scene->named("top");
	const std::vector<btRigidBody*> boxes = scene->dynamicBodies();
	btRigidBody* middle = boxes[1];
	const btScalar middleInvMassBefore = middle->getInvMass();
	const btVector3 middleInvInertiaBefore = middle->getInvInertiaDiagLocal();
	const btVector3 middleGravityBefore = middle->getGravity();

	world.stepSimulation(btScalar(1.0 / 60.0), 1, btScalar(1.0 / 60.0));

	int checked = 0;
	for (const CapturedRow& row : solver.rows)
	{
		if (row.freeBody != top) continue;
		const btScalar expected = handEffectiveMass(*top, row.contactPoint, row.normal);
		// What zeroing only btSolverBody::m_invMass would leave: both bodies' terms.
		const btVector3 rLower = row.contactPoint - middle->getCenterOfMassPosition();
		const btVector3 rxnLower = rLower.cross(row.normal);
		const btScalar bothBodies = btScalar(1) / (btScalar(1) / expected + middle->getInvMass() + rxnLower.dot(middle->getInvInertiaTensorWorld() * rxnLower));
		EXPECT_NEAR(row.effectiveMass, expected, 1e-4 * expected);
		EXPECT_GT(std::fabs(row.effectiveMass - bothBodies), 0.1 * expected);
		++checked;
	}
	EXPECT_GE(checked, 3) << "expected the top box's contact rows in its layer";
	// The fixated body itself was never changed.
	EXPECT_EQ(middle->getInvMass(), middleInvMassBefore);
	EXPECT_EQ(middle->getInvInertiaDiagLocal(), middleInvInertiaBefore);
	EXPECT_EQ(middle->getGravity(), middleGravityBefore);
	EXPECT_EQ(middle->getCollisionFlags() & btCollisionObject::CF_STATIC_OBJECT, 0);
	scene.reset();
}

TEST(BodyFixation, FixatedBodyIsNotMovedByTheLayerAbove)
{
	// Two boxes, f = 0 (no global pass): in layer 1 the bottom box is fixated, so the heavy top
	// box cannot push it; only its own layer (0, against the ground) changes its velocity.
	spec::SceneRun run("mass_ratio_tower", spec::shock(10, 0.0), {{"n", 2}, {"ratio", 1000}});
	run.run(2.0);
	EXPECT_LT(run.worstDrift, 1e-3);
	EXPECT_LT(harness::maxPenetration(*run.sim->world().getDispatcher()), 1e-3);
}

TEST(BodyFixation, ZeroVelocityModeAlsoHoldsTowerOf20)
{
	spec::SceneRun run("tower", spec::shock(), {{"n", 20}});
	btShockPropagationSettings settings = run.sim->shockSolver()->getSettings();
	settings.m_fixationMode = BT_FIXATION_ZERO_VELOCITY;
	run.sim->shockSolver()->setSettings(settings);
	run.run(10.0);
	EXPECT_LT(run.worstDrift, spec::kMaxDriftMeters);
}
