// Bad input: documented safe behaviour, never a crash or NaN spreading into healthy bodies.
#include "Fixture.h"

#include <BulletShockPropagation/btShockPropagationCommon.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
struct BareWorld
{
	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher{&configuration};
	btDbvtBroadphase broadphase;
	std::unique_ptr<btShockPropagationDynamicsWorld> world;
	BareWorld() : world(new btShockPropagationDynamicsWorld(&dispatcher, &broadphase, nullptr, &configuration))
	{
		world->setGravity(btVector3(0, btScalar(-9.81), 0));
	}
	void steps(int n)
	{
		for (int i = 0; i < n; ++i) world->stepSimulation(btScalar(1.0 / 60.0), 1, btScalar(1.0 / 60.0));
	}
};
}  // namespace

TEST(BadInput, NaNVelocityOnOneBodyDoesNotSpreadIntoTheStack)
{
	harness::Trial run(spec::shock(), "tower", {{"n", 5}});
	run.run(0.5);
	btRigidBody* top = run.named("top");
	top->setLinearVelocity(btVector3(std::numeric_limits<btScalar>::quiet_NaN(), 0, 0));
	std::vector<btRigidBody*> healthy;
	for (btRigidBody* b : run.bodies())
		if (b != top) healthy.push_back(b);
	harness::DriftTracker drift(healthy);
	run.run(2.0);
	EXPECT_FALSE(harness::anyNonFinite(healthy));
	EXPECT_LT(drift.maxDrift(), harness::kStandingDriftMeters);
}

TEST(BadInput, InfiniteTransformOnOneBodyDoesNotSpread)
{
	harness::Trial run(spec::shock(), "tower", {{"n", 5}});
	run.run(0.5);
	btRigidBody* top = run.named("top");
	btTransform t = top->getWorldTransform();
	t.getOrigin().setY(std::numeric_limits<btScalar>::infinity());
	top->setWorldTransform(t);
	std::vector<btRigidBody*> healthy;
	for (btRigidBody* b : run.bodies())
		if (b != top) healthy.push_back(b);
	run.run(2.0);
	EXPECT_FALSE(harness::anyNonFinite(healthy));
}

TEST(BadInput, ZeroMassBodyMarkedDynamicActsAsStaticSupport)
{
	harness::Trial run(spec::shock(), "tower", {{"n", 3}});
	btRigidBody* bottom = run.named("bottom");
	run.simulation().world().removeRigidBody(bottom);
	bottom->setMassProps(0, btVector3(0, 0, 0));
	bottom->setCollisionFlags(bottom->getCollisionFlags() & ~btCollisionObject::CF_STATIC_OBJECT);
	run.simulation().world().addRigidBody(bottom);
	run.run(2.0);
	EXPECT_FALSE(harness::anyNonFinite(run.bodies()));
	EXPECT_LT(run.drift().drift(run.named("top")), harness::kStandingDriftMeters);
}

TEST(BadInput, BodyRemovedBetweenStepsLetsTheBoxesAboveFall)
{
	harness::Trial run(spec::shock(), "tower", {{"n", 5}});
	run.run(0.5);
	btRigidBody* middle = run.bodies()[2];
	run.simulation().world().removeRigidBody(middle);
	run.run(2.0);
	EXPECT_FALSE(harness::anyNonFinite(run.bodies()));
	EXPECT_GT(run.drift().drift(run.named("top")), 0.4);  // fell by about one box height (0.5 m)
	EXPECT_LT(run.drift().drift(run.named("bottom")), harness::kStandingDriftMeters);
	run.simulation().world().addRigidBody(middle);  // back, so the scene removes it as usual
}

TEST(BadInput, EmptyWorldSteps)
{
	BareWorld w;
	w.steps(10);
	EXPECT_EQ(w.world->getShockPropagationSolver()->getStatistics().m_numLayers, 0);
}

TEST(BadInput, ManifoldWithZeroPointsIsHarmless)
{
	btBoxShape shape(btVector3(0.5, 0.5, 0.5));
	btRigidBody a(1, nullptr, &shape, btVector3(1, 1, 1));
	btRigidBody b(1, nullptr, &shape, btVector3(1, 1, 1));
	b.getWorldTransform().setOrigin(btVector3(0, 1, 0));
	btPersistentManifold manifold(&a, &b, 0, btScalar(0.02), btScalar(0.02));
	btCollisionObject* bodies[] = {&a, &b};
	btPersistentManifold* manifolds[] = {&manifold};
	btContactSolverInfo info;
	info.m_timeStep = btScalar(1.0 / 60.0);
	btShockPropagationConstraintSolver solver;
	solver.solveGroup(bodies, 2, manifolds, 1, nullptr, 0, info, nullptr, nullptr);
	EXPECT_TRUE(a.getLinearVelocity().isZero());
	EXPECT_TRUE(b.getLinearVelocity().isZero());
}

TEST(BadInput, ConstraintBetweenTwoStaticBodiesIsHarmless)
{
	BareWorld w;
	btBoxShape shape(btVector3(0.5, 0.5, 0.5));
	btRigidBody s1(0, nullptr, &shape);
	btRigidBody s2(0, nullptr, &shape);
	s2.getWorldTransform().setOrigin(btVector3(3, 0, 0));
	btPoint2PointConstraint joint(s1, s2, btVector3(1, 0, 0), btVector3(-1, 0, 0));
	btRigidBody box(1, nullptr, &shape, btVector3(btScalar(1) / 6, btScalar(1) / 6, btScalar(1) / 6));
	box.getWorldTransform().setOrigin(btVector3(0, btScalar(0.99999), 0));
	box.setActivationState(DISABLE_DEACTIVATION);
	w.world->addRigidBody(&s1);
	w.world->addRigidBody(&s2);
	w.world->addRigidBody(&box);
	w.world->addConstraint(&joint);
	w.steps(60);
	EXPECT_TRUE(std::isfinite(box.getCenterOfMassPosition().y()));
	EXPECT_NEAR(box.getCenterOfMassPosition().y(), 1.0, 0.01);
	w.world->removeConstraint(&joint);
	w.world->removeRigidBody(&box);
	w.world->removeRigidBody(&s2);
	w.world->removeRigidBody(&s1);
}

// ---------------------------------------------------------------------------------------------------
// Degenerate collision shapes (issue 37). Each scene: a static ground whose top face is at y = 0, a
// stack of three standard boxes on it (1 x 0.5 x 1 m, 1 kg, mu 0.6; in equilibrium, and it gives the
// plugin layers, so its layered path runs) and the bad input beside or under it, 4 s at 60 Hz. Every
// scene runs under the plugin world, the plugin solver in a stock world and stock Bullet
// (btSequentialImpulseConstraintSolver) for comparison: every transform and velocity stays finite,
// the bad body never moves faster than free fall, and the stack stays within
// harness::kStandingDriftMeters (1 cm) of where it started (stock too, where stock holds it).
// The behaviours, all Bullet's own (the plugin adds nothing for these shapes):
// - a convex hull of 1-3 points collides as its points rounded by the collision margin (0.04 m) and
//   rests on the ground at that height. A hull of 0 points crashes Bullet's collision detection
//   (below): the plugin world refuses it with std::invalid_argument when it is added; in a stock
//   world (stock or solver-only mode) an app must not add one;
// - a sphere of radius 0 has no margin: a point, which rests on the ground (within 1 cm);
// - an empty btCompoundShape collides with nothing and falls freely through the ground. Bullet's
//   calculateLocalInertia gives it zero inertia (its AABB has no extent and the compound's margin is
//   0), which btRigidBody takes as zero inverse inertia (the body does not rotate): an app may pass
//   that value, finite;
// - zero-area triangles (repeated or collinear vertices) among the good ones of a static
//   btBvhTriangleMeshShape leave what rests on them standing.

namespace
{
constexpr int kDegenerateSteps = 240;              // 4 s at 60 Hz
constexpr double kRestOverlapMeters = 1e-5;        // each resting body sinks 10 um into its support (scenes/Scene.h)
constexpr double kGravityMetersPerSecond2 = 9.81;  // harness::Simulation's default
constexpr double kMu = 0.6;

const harness::SolverKind kModes[] = {harness::SolverKind::ShockWorld, harness::SolverKind::ShockSolverOnly, harness::SolverKind::StockSI};

const char* modeName(harness::SolverKind kind)
{
	return kind == harness::SolverKind::ShockWorld ? "world" : kind == harness::SolverKind::ShockSolverOnly ? "solver-only" : "stock";
}

/// Transform (basis included) and both velocities finite.
bool isFiniteBody(const btCollisionObject& object)
{
	const btTransform& t = object.getWorldTransform();
	double sum = double(t.getOrigin().x()) + t.getOrigin().y() + t.getOrigin().z();
	for (int i = 0; i < 3; ++i) sum += double(t.getBasis()[i].x()) + t.getBasis()[i].y() + t.getBasis()[i].z();
	if (const btRigidBody* body = btRigidBody::upcast(&object))
	{
		const btVector3& v = body->getLinearVelocity();
		const btVector3& w = body->getAngularVelocity();
		sum += double(v.x()) + v.y() + v.z() + w.x() + w.y() + w.z();
	}
	return std::isfinite(sum);
}

/// What one run of a StackBeside scene did.
struct Outcome
{
	int firstNonFiniteStep = 0;  ///< first step after which some body was not finite (0: none)
	std::string nonFiniteBody;   ///< which one, at that step
	double stackDrift = 0;       ///< m, largest displacement of a stack box over all steps
	double maxOddSpeed = 0;      ///< m/s, largest speed of the bad body over all steps
	int layers = 0;              ///< most stack layers in one step (plugin only)
};

/// The three-box stack at x = 0 on `groundShape` (static, placed at `groundAt`) under one mode; the
/// test adds its bad body with addOdd().
struct StackBeside
{
	harness::Simulation sim;
	scenes::SceneContent content{sim.world()};  // after sim: removes its bodies while the world exists
	std::vector<btRigidBody*> stack;
	btRigidBody* odd = nullptr;

	StackBeside(harness::SolverKind kind, btCollisionShape* groundShape, const btTransform& groundAt)
		: sim(kind == harness::SolverKind::StockSI ? spec::stock() : spec::plugin(kind), spec::kTimeStepSeconds, kGravityMetersPerSecond2)
	{
		content.addBody(groundShape, 0, groundAt, btScalar(kMu));
		btCollisionShape* box = content.addShape(new btBoxShape(btVector3(btScalar(0.5), btScalar(0.25), btScalar(0.5))));
		for (int level = 0; level < 3; ++level)
		{
			const double y = level * (0.5 - kRestOverlapMeters) + 0.25 - kRestOverlapMeters;
			stack.push_back(content.addBody(box, 1, btTransform(btQuaternion::getIdentity(), btVector3(0, btScalar(y), 0)), btScalar(kMu)));
		}
	}

	/// The bad body: `shape` (owned by the scene), 1 kg with the inertia Bullet's calculateLocalInertia
	/// gives (as an app would), at rest at `origin`.
	void addOdd(btCollisionShape* shape, const btVector3& origin)
	{
		odd = content.addBody(shape, 1, btTransform(btQuaternion::getIdentity(), origin), btScalar(kMu));
	}

	Outcome run(int steps)
	{
		Outcome out;
		harness::DriftTracker drift(stack);
		const btCollisionObjectArray& objects = sim.world().getCollisionObjectArray();
		for (int step = 1; step <= steps; ++step)
		{
			sim.step();
			for (int i = 0; i < objects.size() && !out.firstNonFiniteStep; ++i)
			{
				if (isFiniteBody(*objects[i])) continue;
				out.firstNonFiniteStep = step;
				out.nonFiniteBody = objects[i] == odd ? "the bad body" : objects[i]->isStaticObject() ? "the ground" : "a stack box";
			}
			out.stackDrift = std::max(out.stackDrift, drift.maxDrift());
			if (odd) out.maxOddSpeed = std::max(out.maxOddSpeed, double(odd->getLinearVelocity().length()));
			if (sim.shockSolver()) out.layers = std::max(out.layers, sim.shockSolver()->getStatistics().m_numLayers);
		}
		return out;
	}
};

btTransform groundBoxAt() { return btTransform(btQuaternion::getIdentity(), btVector3(0, btScalar(-0.5), 0)); }
btCollisionShape* groundBox() { return new btBoxShape(btVector3(50, btScalar(0.5), 50)); }
/// Where the bad body starts: 1.5 m beside the stack (0.5 m clear of it), 0.5 m up.
btVector3 oddStart() { return btVector3(btScalar(1.5), btScalar(0.5), 0); }

/// What every mode must do in every scene below (the stack's drift only if `stackMustStand`);
/// prints the figures for the report.
void expectSafe(const std::string& scene, harness::SolverKind kind, const Outcome& out, const btRigidBody* odd, bool stackMustStand = true)
{
	SCOPED_TRACE(scene + ", " + modeName(kind));
	const std::string finite = out.firstNonFiniteStep ? "NON-FINITE: " + out.nonFiniteBody + " at step " + std::to_string(out.firstNonFiniteStep) : "finite";
	char oddText[96] = "no bad body";
	if (odd) std::snprintf(oddText, sizeof oddText, "bad body at y %.4g m, fastest %.3g m/s", double(odd->getCenterOfMassPosition().y()), out.maxOddSpeed);
	std::printf("BADINPUT | %s | %s | stack drift %.3g cm | %s | layers %d | %s\n", scene.c_str(), modeName(kind), 100 * out.stackDrift, oddText, out.layers,
				finite.c_str());
	EXPECT_EQ(out.firstNonFiniteStep, 0) << out.nonFiniteBody << " not finite";
	if (stackMustStand)
	{
		EXPECT_LT(out.stackDrift, harness::kStandingDriftMeters);
	}
	// Nothing faster than free fall over the whole run (no energy from the bad input).
	EXPECT_LE(out.maxOddSpeed, 1.01 * kGravityMetersPerSecond2 * kDegenerateSteps * spec::kTimeStepSeconds);
	if (kind != harness::SolverKind::StockSI)
	{
		EXPECT_GE(out.layers, 2) << "the stack was not layered";
	}
}

/// A hull of `points` (hull-local), 1 kg, dropped beside the stack; returns how far its origin ends
/// above the ground, less the hull's collision margin (m).
double dropHullBesideStack(harness::SolverKind kind, const std::vector<btVector3>& points)
{
	StackBeside s(kind, groundBox(), groundBoxAt());
	btConvexHullShape* hull = new btConvexHullShape(points.empty() ? nullptr : &points[0].getX(), int(points.size()), sizeof(btVector3));
	s.addOdd(hull, oddStart());
	expectSafe("hull of " + std::to_string(points.size()) + " points", kind, s.run(kDegenerateSteps), s.odd);
	return double(s.odd->getCenterOfMassPosition().y()) - hull->getMargin();
}

/// The stack on a static mesh ground: a grid of 1 m cells (two triangles each) over [-3.25, 2.75]^2
/// at y = 0 (cell edges off the boxes' edges) and, if `zeroArea`, zero-area triangles under the
/// stack's bottom face and at its corner: two vertices equal, all three equal, collinear, and
/// collinear through a grid vertex.
Outcome stackOnMesh(harness::SolverKind kind, bool zeroArea)
{
	btTriangleMesh* mesh = new btTriangleMesh();
	for (int i = 0; i < 6; ++i)
		for (int k = 0; k < 6; ++k)
		{
			const btScalar x0 = btScalar(-3.25 + i), z0 = btScalar(-3.25 + k);
			const btVector3 a(x0, 0, z0), b(x0 + 1, 0, z0), c(x0 + 1, 0, z0 + 1), d(x0, 0, z0 + 1);
			mesh->addTriangle(a, b, c, false);
			mesh->addTriangle(a, c, d, false);
		}
	if (zeroArea)
	{
		const btVector3 p(btScalar(-0.3), 0, btScalar(-0.3)), q(btScalar(0.3), 0, btScalar(0.1)), r(btScalar(0.1), 0, btScalar(0.2));
		mesh->addTriangle(p, p, q, false);
		mesh->addTriangle(r, r, r, false);
		mesh->addTriangle(btVector3(btScalar(-0.4), 0, btScalar(0.4)), btVector3(0, 0, 0), btVector3(btScalar(0.4), 0, btScalar(-0.4)), false);
		mesh->addTriangle(btVector3(btScalar(-0.25), 0, btScalar(-0.25)), btVector3(btScalar(0.25), 0, btScalar(0.25)),
						  btVector3(btScalar(0.75), 0, btScalar(0.75)), false);
		mesh->addTriangle(btVector3(btScalar(0.5), 0, btScalar(0.5)), btVector3(btScalar(0.5), 0, btScalar(0.5)), btVector3(btScalar(0.6), 0, btScalar(0.5)), false);
	}
	StackBeside s(kind, new btBvhTriangleMeshShape(mesh, true), btTransform::getIdentity());
	s.content.keep(mesh);
	return s.run(kDegenerateSteps);
}
}  // namespace

TEST(BadInput, ConvexHullOfFewerThanFourPointsRestsBesideAStack)
{
	// A point, a segment, a flat triangle (at hull-local y = 0): each lands and rests on the ground,
	// its points one collision margin above it.
	const std::vector<std::vector<btVector3>> hulls = {
		{btVector3(0, 0, 0)},
		{btVector3(btScalar(-0.2), 0, 0), btVector3(btScalar(0.2), 0, 0)},
		{btVector3(btScalar(-0.2), 0, btScalar(-0.2)), btVector3(btScalar(0.2), 0, btScalar(-0.2)), btVector3(0, 0, btScalar(0.2))},
	};
	for (const std::vector<btVector3>& points : hulls)
		for (harness::SolverKind kind : kModes)
			EXPECT_NEAR(dropHullBesideStack(kind, points), 0, 0.01) << points.size() << " points, " << modeName(kind);

	// No points: Bullet's support function (convexHullSupport, btConvexShape.cpp) reads point 0 of the
	// empty array, a null pointer, from GJK in the first collision test with the ground (step 16): a
	// crash (SIGSEGV) in every mode, stock included, inside performDiscreteCollisionDetection before
	// any solver runs. Pinned here so that a change (a clear error instead) shows.
	// The plugin world refuses such a body with a clear error when it is added; the others crash.
	::testing::FLAGS_gtest_death_test_style = "threadsafe";
	for (harness::SolverKind kind : kModes)
	{
		if (kind == harness::SolverKind::ShockWorld)
			EXPECT_THROW(dropHullBesideStack(kind, {}), std::invalid_argument) << modeName(kind);
		else
			EXPECT_DEATH(dropHullBesideStack(kind, {}), "") << modeName(kind);
	}
}

TEST(BadInput, WorldThatRefusedAnEmptyHullStepsOn)
{
	// The refusal leaves the world as it was: the stack beside it steps on and stands.
	StackBeside s(harness::SolverKind::ShockWorld, groundBox(), groundBoxAt());
	EXPECT_THROW(s.addOdd(new btConvexHullShape(), oddStart()), std::invalid_argument);
	EXPECT_EQ(s.sim.world().getNumCollisionObjects(), 4);  // the ground and the three boxes
	const Outcome out = s.run(kDegenerateSteps);
	EXPECT_EQ(out.firstNonFiniteStep, 0) << out.nonFiniteBody;
	EXPECT_LT(out.stackDrift, harness::kStandingDriftMeters);
}

TEST(BadInput, SphereOfRadiusZeroRestsBesideAStack)
{
	for (harness::SolverKind kind : kModes)
	{
		StackBeside s(kind, groundBox(), groundBoxAt());
		s.addOdd(new btSphereShape(0), oddStart());
		expectSafe("sphere of radius 0", kind, s.run(kDegenerateSteps), s.odd);
		EXPECT_NEAR(s.odd->getCenterOfMassPosition().y(), 0, 0.01) << modeName(kind);  // a point on the ground
	}
}

TEST(BadInput, EmptyCompoundBesideAStackFallsFreely)
{
	btCompoundShape empty;
	btVector3 inertia(1, 1, 1);
	empty.calculateLocalInertia(1, inertia);
	EXPECT_TRUE(inertia.isZero()) << "Bullet's inertia of an empty compound: " << inertia.x() << " " << inertia.y() << " " << inertia.z();
	for (harness::SolverKind kind : kModes)
	{
		StackBeside s(kind, groundBox(), groundBoxAt());
		s.addOdd(new btCompoundShape(), oddStart());
		expectSafe("empty compound", kind, s.run(kDegenerateSteps), s.odd);
		// Nothing to collide with: Bullet's free fall (semi-implicit Euler, no damping), y0 - g dt^2 n (n + 1) / 2.
		const double n = kDegenerateSteps, dt = spec::kTimeStepSeconds;
		EXPECT_NEAR(s.odd->getCenterOfMassPosition().y(), oddStart().y() - kGravityMetersPerSecond2 * dt * dt * n * (n + 1) / 2, 0.01) << modeName(kind);
		EXPECT_NEAR(s.odd->getCenterOfMassPosition().x(), oddStart().x(), 1e-6) << modeName(kind);
	}
}

TEST(BadInput, TriangleMeshGroundWithZeroAreaTrianglesHoldsAStack)
{
	for (harness::SolverKind kind : kModes)
	{
		// Stock SI lets the stack creep 1.1-1.3 cm on this mesh with or without the zero-area triangles
		// (not the bad input's doing): its drift is printed beside the clean mesh's, not asserted.
		const bool plugin = kind != harness::SolverKind::StockSI;
		const Outcome clean = stackOnMesh(kind, false);
		std::printf("BADINPUT | mesh ground without zero-area triangles | %s | stack drift %.3g cm\n", modeName(kind), 100 * clean.stackDrift);
		expectSafe("mesh ground with zero-area triangles", kind, stackOnMesh(kind, true), nullptr, plugin);
		if (plugin)
		{
			EXPECT_LT(clean.stackDrift, harness::kStandingDriftMeters);
		}
	}
}

TEST(World, RejectsASolverOfAnotherTypeAtConstruction)
{
	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher(&configuration);
	btDbvtBroadphase broadphase;
	btSequentialImpulseConstraintSolver stock;
	EXPECT_THROW(btShockPropagationDynamicsWorld(&dispatcher, &broadphase, &stock, &configuration), std::invalid_argument);
}

TEST(World, CreatesAndOwnsItsSolverWhenGivenNull)
{
	BareWorld w;
	ASSERT_NE(w.world->getShockPropagationSolver(), nullptr);
	EXPECT_EQ(w.world->getConstraintSolver(), w.world->getShockPropagationSolver());
	btSequentialImpulseConstraintSolver stock;
	EXPECT_THROW(w.world->setConstraintSolver(&stock), std::invalid_argument);
	EXPECT_EQ(w.world->getConstraintSolver(), w.world->getShockPropagationSolver());
}

TEST(Settings, WeightingIsClampedAndNaNIgnored)
{
	btShockPropagationConstraintSolver solver;
	EXPECT_EQ(solver.getWeighting(), btShockPropagationSettings().m_weighting);
	solver.setWeighting(2);
	EXPECT_EQ(solver.getWeighting(), btScalar(1));
	solver.setWeighting(-1);
	EXPECT_EQ(solver.getWeighting(), btScalar(0));
	solver.setWeighting(btScalar(0.25));
	solver.setWeighting(std::numeric_limits<btScalar>::quiet_NaN());
	EXPECT_EQ(solver.getWeighting(), btScalar(0.25));
}
