// Fixation is an infinite-mass override of the rows Bullet built: the effective mass of a row
// between a free body and a fixated one is the free body's alone, and the fixated btRigidBody is
// never modified.
#include "Fixture.h"

#include <BulletShockPropagation/btShockPropagationCommon.h>

#include "btLayerFixation.h"  // private to the plugin (plugin/src)

#include <cmath>

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

/// Bullet's own row setup, run on the side: exposes the rows it builds for a world's manifolds.
class RowBuilder : public btSequentialImpulseConstraintSolver
{
public:
	void build(btDiscreteDynamicsWorld& world)
	{
		btAlignedObjectArray<btCollisionObject*> bodies;
		for (int i = 0; i < world.getNumCollisionObjects(); ++i)
			if (!world.getCollisionObjectArray()[i]->isStaticObject()) bodies.push_back(world.getCollisionObjectArray()[i]);
		btDispatcher& dispatcher = *world.getDispatcher();
		btContactSolverInfo info = world.getSolverInfo();
		info.m_solverMode = 0;  // no warm start: rows only
		solveGroupCacheFriendlySetup(&bodies[0], bodies.size(), dispatcher.getInternalManifoldPointer(), dispatcher.getNumManifolds(),
									 nullptr, 0, info, nullptr);
	}
	~RowBuilder() override
	{
		for (int i = 0; i < m_tmpSolverBodyPool.size(); ++i)
			if (m_tmpSolverBodyPool[i].m_originalBody) m_tmpSolverBodyPool[i].m_originalBody->setCompanionId(-1);
	}
	btAlignedObjectArray<btSolverBody>& bodyPool() { return m_tmpSolverBodyPool; }
	btConstraintArray& contactRows() { return m_tmpSolverContactConstraintPool; }
};

/// Calls visit(row, a, b, fixA, fixB) for each contact row between `upper` and the fixated `lower`
/// (fixA: lower is the row's body A); returns how many there were.
template <class Visit>
int visitRowsOnFixated(RowBuilder& builder, const btRigidBody* upper, const btRigidBody* lower, Visit visit)
{
	int visited = 0;
	for (int i = 0; i < builder.contactRows().size(); ++i)
	{
		btSolverConstraint& row = builder.contactRows()[i];
		btSolverBody& a = builder.bodyPool()[row.m_solverBodyIdA];
		btSolverBody& b = builder.bodyPool()[row.m_solverBodyIdB];
		const bool fixA = a.m_originalBody == lower && b.m_originalBody == upper;
		const bool fixB = b.m_originalBody == lower && a.m_originalBody == upper;
		if (!fixA && !fixB) continue;
		visit(row, a, b, fixA, fixB);
		++visited;
	}
	return visited;
}

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
	// Three boxes: the middle one is fixated under the top one in layer 1; a row that also counted
	// the middle box's inverse mass and inertia would be far from the hand value.
	harness::Trial run(spec::shock(), "tower", {{"n", 3}});
	run.run(spec::kTimeStepSeconds);
	btRigidBody* top = run.scene().named("top");
	btRigidBody* middle = run.bodies()[1];
	const btScalar middleInvMassBefore = middle->getInvMass();
	const btVector3 middleInvInertiaBefore = middle->getInvInertiaDiagLocal();
	RowBuilder builder;
	builder.build(run.simulation().world());
	btLayerFixationParams params;
	const int checked = visitRowsOnFixated(builder, top, middle, [&](btSolverConstraint& row, btSolverBody& a, btSolverBody& b, bool fixA, bool fixB) {
		const btManifoldPoint* cp = static_cast<const btManifoldPoint*>(row.m_originalContactPoint);
		const btVector3 point = fixA ? cp->getPositionWorldOnB() : cp->getPositionWorldOnA();
		const btScalar expected = handEffectiveMass(*top, point, cp->m_normalWorldOnB);
		const btScalar before = row.m_jacDiagABInv;
		btFixateSolverRow(row, BT_ROW_CONTACT, a, b, fixA, fixB, params, cp->m_normalWorldOnB);
		EXPECT_NEAR(row.m_jacDiagABInv, expected, 1e-4 * expected);
		EXPECT_GT(std::fabs(row.m_jacDiagABInv - before), 0.1 * expected) << "the row as set up counted both bodies";
		EXPECT_TRUE((fixA ? row.m_angularComponentA : row.m_angularComponentB).isZero()) << "impulses must not turn the fixated body";
	});
	EXPECT_GE(checked, 3) << "expected the top box's contact rows on the middle box";
	// The fixated body itself was never changed.
	EXPECT_EQ(middle->getInvMass(), middleInvMassBefore);
	EXPECT_EQ(middle->getInvInertiaDiagLocal(), middleInvInertiaBefore);
}

TEST(BodyFixation, FixatedBodyIsNotMovedByTheLayerAbove)
{
	// Two boxes, f = 0 (no global pass): in layer 1 the bottom box is fixated, so the heavy top
	// box cannot push it; only its own layer (0, against the ground) changes its velocity.
	harness::Trial run(spec::shock(10, 0.0), "mass_ratio_tower", {{"n", 2}, {"ratio", 1000}});
	run.run(2.0);
	EXPECT_LT(run.maxDrift(), 1e-3);
	EXPECT_LT(harness::maxPenetration(*run.simulation().world().getDispatcher()), 1e-3);
}

TEST(BodyFixation, ZeroVelocityModeAlsoHoldsTowerOf20)
{
	harness::Trial run(spec::shock(), "tower", {{"n", 20}});
	btShockPropagationSettings settings = run.simulation().shockSolver()->getSettings();
	settings.m_fixationMode = BT_FIXATION_ZERO_VELOCITY;
	run.simulation().shockSolver()->setSettings(settings);
	run.run(10.0);
	EXPECT_LT(run.maxDrift(), harness::kStandingDriftMeters);
}

TEST(BodyFixation, ASupportSlowerThanTheRestSpeedShowsNoMotion)
{
	// D32 (docs/design.md, section 4t): along a contact row, a fixated support that nothing drives
	// and whose shown motion (D1: linear velocity and spin about the normal) is slower than the rest
	// speed is fixated as at rest (as zero-velocity fixation would); faster, it shows that motion.
	harness::Trial run(spec::shock(), "tower", {{"n", 3}});
	run.run(spec::kTimeStepSeconds);
	btRigidBody* top = run.scene().named("top");
	btRigidBody* middle = run.bodies()[1];
	RowBuilder builder;
	builder.build(run.simulation().world());
	const btScalar restSpeed = btScalar(1e-3);
	const int checked = visitRowsOnFixated(builder, top, middle, [&](btSolverConstraint& row, btSolverBody& a, btSolverBody& b, bool fixA, bool fixB) {
		btSolverBody& support = fixA ? a : b;
		const btVector3 normal = static_cast<const btManifoldPoint*>(row.m_originalContactPoint)->m_normalWorldOnB;
		// The support moves along the normal only (no gravity impulse left, no spin): what it shows
		// along this row is that speed.
		support.m_externalForceImpulse.setZero();
		support.m_externalTorqueImpulse.setZero();
		support.m_angularVelocity.setZero();
		const btSolverConstraint original = row;
		auto fixated = [&](btScalar speed, btShockPropagationFixationMode mode, btScalar rest, bool driven = false) {
			support.m_linearVelocity = normal * speed;
			btSolverConstraint copy = original;
			btLayerFixationParams params;
			params.m_mode = mode;
			params.m_restSpeed = rest;
			btFixateSolverRow(copy, BT_ROW_CONTACT, a, b, fixA, fixB, params, normal, fixA && driven, fixB && driven);
			return copy.m_rhs;
		};
		for (btScalar share : {btScalar(0.5), btScalar(2)})
		{
			const btScalar speed = share * restSpeed;
			const btScalar withRest = fixated(speed, BT_FIXATION_KEEP_LINEAR_AND_TWIST, restSpeed);
			const btScalar atRest = fixated(speed, BT_FIXATION_ZERO_VELOCITY, 0);
			const btScalar shown = fixated(speed, BT_FIXATION_KEEP_LINEAR_AND_TWIST, 0);
			// The two fixations differ by the shown speed times the row's effective mass.
			ASSERT_GT(std::fabs(shown - atRest), 0.4 * speed * original.m_jacDiagABInv);
			// A driven support (a joint, a moving kinematic body) shows its motion however slow.
			EXPECT_EQ(fixated(speed, BT_FIXATION_KEEP_LINEAR_AND_TWIST, restSpeed, true), shown);
			if (share < 1)
				EXPECT_EQ(withRest, atRest) << "a support slower than the rest speed is at rest";
			else
				EXPECT_EQ(withRest, shown) << "a support faster than the rest speed shows its motion";
		}
	});
	EXPECT_GE(checked, 3) << "expected the top box's contact rows on the middle box";
}
