// Conservation specs of the plugin's velocity step (docs/design.md), built as an app builds its world (Bullet's defaults, 60 Hz, 10
// iterations, sleeping off), world and solver-only mode.
//
// On a frictionless static floor nothing acts on a stack horizontally but its own contacts, so its
// horizontal momentum and its angular momentum about the vertical must stay at their start values;
// the bound is 1e-6 of m g t (round-off). Modes: stock SI, the plugin in world and solver-only
// mode, and its classic order (no weight feeling). Expected values come from physics, and stock
// Bullet runs in the same test where the claim is "no worse than stock". Each test prints one line
//   CONSERVATION | <case> | stock ... | world ... | solver ... | classic ...
// before it asserts.

#include <BulletShockPropagation/btShockPropagationCommon.h>
#include <btBulletDynamicsCommon.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace
{
enum class Mode
{
	Stock,
	World,
	Solver,
	Classic  ///< the plugin without weight feeling (Erleben's classic order), world mode
};
const int kNumModes = 4;
const char* kModeNames[] = {"stock", "world", "solver", "classic"};
const btScalar kDt = btScalar(1) / btScalar(60);
const btScalar kG = btScalar(9.81);

/// A column of boxes 1 x 0.5 x 1 m on a static box floor of friction floorMu (box-box friction
/// 0.6 combined), each box given velocity v0 along x; the top box weighs topMass, the others 1 kg.
struct Column
{
	std::unique_ptr<btDefaultCollisionConfiguration> configuration{new btDefaultCollisionConfiguration};
	std::unique_ptr<btCollisionDispatcher> dispatcher{new btCollisionDispatcher(configuration.get())};
	std::unique_ptr<btDbvtBroadphase> broadphase{new btDbvtBroadphase};
	std::unique_ptr<btConstraintSolver> solver;
	std::unique_ptr<btDiscreteDynamicsWorld> world;
	btBoxShape floorShape{btVector3(50, btScalar(0.5), 50)};
	btBoxShape boxShape{btVector3(btScalar(0.5), btScalar(0.25), btScalar(0.5))};
	std::vector<std::unique_ptr<btDefaultMotionState>> states;
	std::vector<std::unique_ptr<btRigidBody>> bodies;  // [0]: the floor

	/// n boxes of 1 kg, the top one topMass.
	Column(Mode mode, int n, btScalar topMass, btScalar floorMu, btScalar v0) : Column(mode, unitMassesUnder(n, topMass), floorMu, v0) {}
	/// masses: each box's, bottom first.
	Column(Mode mode, const std::vector<btScalar>& masses, btScalar floorMu, btScalar v0)
	{
		btShockPropagationSettings settings;
		settings.m_weightFeeling = mode != Mode::Classic;
		if (mode == Mode::Stock)
			solver.reset(new btSequentialImpulseConstraintSolver);
		else
			solver.reset(new btShockPropagationConstraintSolver(settings));
		if (mode == Mode::Solver || mode == Mode::Stock)
			world.reset(new btDiscreteDynamicsWorld(dispatcher.get(), broadphase.get(), solver.get(), configuration.get()));
		else
			world.reset(new btShockPropagationDynamicsWorld(dispatcher.get(), broadphase.get(), solver.get(), configuration.get()));
		world->setGravity(btVector3(0, -kG, 0));
		add(0, btVector3(0, btScalar(-0.5), 0), &floorShape, floorMu);
		for (size_t i = 0; i < masses.size(); ++i)
		{
			// 10 micrometres of overlap per contact, so every contact exists at the first step.
			const btVector3 at(0, btScalar(0.25) + btScalar(0.5) * btScalar(i) - btScalar(1e-5) * btScalar(i + 1), 0);
			btRigidBody* body = add(masses[i], at, &boxShape, btScalar(0.6));
			body->setLinearVelocity(btVector3(v0, 0, 0));
		}
	}
	static std::vector<btScalar> unitMassesUnder(int n, btScalar topMass)
	{
		std::vector<btScalar> masses(size_t(std::max(n, 0)), btScalar(1));
		if (!masses.empty()) masses.back() = topMass;
		return masses;
	}
	~Column()
	{
		for (auto& body : bodies) world->removeRigidBody(body.get());
	}
	btRigidBody* add(btScalar mass, const btVector3& at, btCollisionShape* shape, btScalar friction)
	{
		btVector3 inertia(0, 0, 0);
		if (mass > 0) shape->calculateLocalInertia(mass, inertia);
		states.emplace_back(new btDefaultMotionState(btTransform(btQuaternion::getIdentity(), at)));
		bodies.emplace_back(new btRigidBody(mass, states.back().get(), shape, inertia));
		btRigidBody* body = bodies.back().get();
		body->setFriction(friction);
		body->setActivationState(DISABLE_DEACTIVATION);
		world->addRigidBody(body);
		return body;
	}
	btScalar totalMass() const
	{
		btScalar m = 0;
		for (size_t i = 1; i < bodies.size(); ++i) m += btScalar(1) / bodies[i]->getInvMass();
		return m;
	}
	/// Horizontal momentum (kg m/s) and angular momentum about the vertical through the origin (kg m^2/s).
	btScalar horizontalMomentum() const
	{
		btVector3 p(0, 0, 0);
		for (size_t i = 1; i < bodies.size(); ++i) p += bodies[i]->getLinearVelocity() / bodies[i]->getInvMass();
		return btSqrt(p.x() * p.x() + p.z() * p.z());
	}
	btScalar verticalAngularMomentum() const
	{
		btScalar l = 0;
		for (size_t i = 1; i < bodies.size(); ++i)
		{
			const btRigidBody* b = bodies[i].get();
			const btVector3 spin = b->getInvInertiaTensorWorld().inverse() * b->getAngularVelocity();
			l += spin.y() + b->getCenterOfMassPosition().cross(b->getLinearVelocity() / b->getInvMass()).y();
		}
		return l;
	}
	/// Kinetic energy in the frame of the column's centre of mass (J).
	btScalar internalKineticEnergy() const
	{
		btVector3 p(0, 0, 0);
		for (size_t i = 1; i < bodies.size(); ++i) p += bodies[i]->getLinearVelocity() / bodies[i]->getInvMass();
		const btVector3 vc = p / totalMass();
		btScalar e = 0;
		for (size_t i = 1; i < bodies.size(); ++i)
		{
			const btRigidBody* b = bodies[i].get();
			const btVector3 v = b->getLinearVelocity() - vc;
			e += btScalar(0.5) * (v.length2() / b->getInvMass() + b->getAngularVelocity().dot(b->getInvInertiaTensorWorld().inverse() * b->getAngularVelocity()));
		}
		return e;
	}
	/// Kinetic energy (J) and potential energy in gravity above y = 0 (J) of the boxes.
	btScalar kineticEnergy() const
	{
		btScalar e = 0;
		for (size_t i = 1; i < bodies.size(); ++i)
		{
			const btRigidBody* b = bodies[i].get();
			e += btScalar(0.5) * (b->getLinearVelocity().length2() / b->getInvMass() +
								  b->getAngularVelocity().dot(b->getInvInertiaTensorWorld().inverse() * b->getAngularVelocity()));
		}
		return e;
	}
	btScalar potentialEnergy() const
	{
		btScalar e = 0;
		for (size_t i = 1; i < bodies.size(); ++i) e += kG * bodies[i]->getCenterOfMassPosition().y() / bodies[i]->getInvMass();
		return e;
	}
	/// Largest horizontal distance between any box's centre and the bottom box's (m).
	btScalar spread() const
	{
		btScalar s = 0;
		const btVector3 base = bodies[1]->getCenterOfMassPosition();
		for (size_t i = 2; i < bodies.size(); ++i)
		{
			btVector3 d = bodies[i]->getCenterOfMassPosition() - base;
			d.setY(0);
			s = btMax(s, d.length());
		}
		return s;
	}
};

struct Outcome
{
	btScalar momentum = 0;         // largest horizontal momentum over the run (kg m/s)
	btScalar angular = 0;          // largest |angular momentum about the vertical| change (kg m^2/s)
	btScalar spread = 0;           // largest spread over the run's last half (m)
	btScalar internalEnergy = 0;   // largest kinetic energy in the centre's frame, last half (J)
	btScalar momentumBound = 0;    // 1e-6 m g t
	btScalar startMomentum = 0;
};

Outcome run(Mode mode, int n, btScalar topMass, btScalar v0, btScalar seconds)
{
	Column column(mode, n, topMass, 0, v0);
	Outcome out;
	out.startMomentum = column.horizontalMomentum();
	const btScalar startAngular = column.verticalAngularMomentum();
	const int steps = int(seconds / kDt + btScalar(0.5));
	for (int s = 0; s < steps; ++s)
	{
		column.world->stepSimulation(kDt, 0, kDt);
		out.momentum = btMax(out.momentum, btFabs(column.horizontalMomentum() - out.startMomentum));
		out.angular = btMax(out.angular, btFabs(column.verticalAngularMomentum() - startAngular));
		if (s >= steps / 2)
		{
			out.spread = btMax(out.spread, column.spread());
			out.internalEnergy = btMax(out.internalEnergy, column.internalKineticEnergy());
		}
	}
	out.momentumBound = btScalar(1e-6) * column.totalMass() * kG * seconds;
	return out;
}

void report(const char* name, const Outcome* o)
{
	std::printf("CONSERVATION | %s", name);
	for (int m = 0; m < kNumModes; ++m)
		std::printf(" | %s dp %.2g kg m/s dL %.2g spread %.3g cm KE %.2g J", kModeNames[m], double(o[m].momentum), double(o[m].angular),
					double(o[m].spread * 100), double(o[m].internalEnergy));
	std::printf(" | bound dp %.2g\n", double(o[0].momentumBound));
}
}  // namespace

// Three 1 kg boxes at rest on ice: nothing pushes them, so they stay where they are.
TEST(Conservation, ColumnAtRestOnIceKeepsItsMomentum)
{
	Outcome o[kNumModes];
	for (int m = 0; m < kNumModes; ++m) o[m] = run(Mode(m), 3, 1, 0, 10);
	report("column of 3 at rest on ice", o);
	EXPECT_LE(o[int(Mode::Classic)].momentum, o[int(Mode::Classic)].momentumBound);
	for (Mode m : {Mode::World, Mode::Solver})
	{
		const Outcome& r = o[int(m)];
		EXPECT_LE(r.momentum, r.momentumBound) << kModeNames[int(m)];
		EXPECT_LE(r.angular, r.momentumBound) << kModeNames[int(m)];
		EXPECT_LE(r.spread, btScalar(1e-3)) << kModeNames[int(m)];           // it stands
		EXPECT_LE(r.internalEnergy, btScalar(1e-9) + o[int(Mode::Stock)].internalEnergy) << kModeNames[int(m)];
	}
}

// The same boxes given 0.5 mm/s together: physics says they coast as one body.
TEST(Conservation, CoastingColumnOnIceCoastsAsOne)
{
	const btScalar v0 = btScalar(5e-4);
	Outcome o[kNumModes];
	for (int m = 0; m < kNumModes; ++m) o[m] = run(Mode(m), 3, 1, v0, 10);
	report("column of 3 coasting on ice at 0.5 mm/s", o);
	EXPECT_LE(o[int(Mode::Classic)].momentum, o[int(Mode::Classic)].momentumBound);
	for (Mode m : {Mode::World, Mode::Solver})
	{
		const Outcome& r = o[int(m)];
		EXPECT_NEAR(r.startMomentum, btScalar(3) * v0, btScalar(1e-9));
		EXPECT_LE(r.momentum, r.momentumBound) << kModeNames[int(m)];
		EXPECT_LE(r.spread, btMax(btScalar(1e-3), o[int(Mode::Stock)].spread)) << kModeNames[int(m)];
		EXPECT_LE(r.internalEnergy, btScalar(1e-9) + o[int(Mode::Stock)].internalEnergy) << kModeNames[int(m)];
	}
}

// BenchmarkDemo's 1000:1 column (three 1 kg boxes under a 1000 kg one) on ice, which is in
// equilibrium: the plugin keeps its horizontal momentum and it stands (every box within
// 1 cm, kinetic energy at most m_top g times one 10 micrometre rest overlap). Stock SI and the
// classic order crush it; their crushed boxes sink into the floor box and meet its sides, whose
// horizontal normals turn them about the vertical, so for them only the linear momentum is a law.
TEST(Conservation, HeavyTopColumnOnIceKeepsItsMomentum)
{
	Outcome o[kNumModes];
	for (int m = 0; m < kNumModes; ++m) o[m] = run(Mode(m), 4, 1000, 0, 5);
	report("1000:1 column on ice", o);
	for (Mode m : {Mode::Stock, Mode::World, Mode::Solver, Mode::Classic})
		EXPECT_LE(o[int(m)].momentum, o[int(m)].momentumBound) << kModeNames[int(m)];
	for (Mode m : {Mode::World, Mode::Solver})
	{
		EXPECT_LE(o[int(m)].spread, btScalar(0.01)) << kModeNames[int(m)];
		EXPECT_LE(o[int(m)].internalEnergy, btScalar(1000) * kG * btScalar(1e-5)) << kModeNames[int(m)];
	}
}

/// Stock, world and solver-only runs of one column on the floor for 2 s (masses bottom first):
/// the largest kinetic energy beyond the potential energy released so far, the energy released
/// at the end, and whether the kinetic energy stayed finite, printed under label.
struct EnergyExcess
{
	const char* names[3] = {"stock", "world", "solver"};
	btScalar excess[3] = {0, 0, 0};    // largest (kinetic - released potential) over the run (J)
	btScalar released[3] = {0, 0, 0};  // potential energy released at the end (J)
	bool finite[3] = {true, true, true};
};

EnergyExcess measureEnergyExcess(const std::vector<btScalar>& masses, const char* label)
{
	EnergyExcess e;
	const Mode modes[] = {Mode::Stock, Mode::World, Mode::Solver};
	for (int m = 0; m < 3; ++m)
	{
		Column column(modes[m], masses, btScalar(0.5), 0);
		const btScalar potential0 = column.potentialEnergy();
		for (int s = 0; s < 120; ++s)
		{
			column.world->stepSimulation(kDt, 0, kDt);
			const btScalar give = potential0 - column.potentialEnergy();
			e.excess[m] = btMax(e.excess[m], column.kineticEnergy() - btMax(btScalar(0), give));
			e.released[m] = give;
			e.finite[m] = e.finite[m] && std::isfinite(double(column.kineticEnergy()));
		}
	}
	std::printf("CONSERVATION | %s | kinetic minus released potential, largest over 2 s:", label);
	for (int m = 0; m < 3; ++m) std::printf(" %s %.3g J (released %.3g J)", e.names[m], double(e.excess[m]), double(e.released[m]));
	std::printf("\n");
	return e;
}

// A 1e5 kg box on a 1 kg box on the floor: the row between them has s = 1e5 + 1, beyond the
// predictor's fixation limit (2.9e3 in both precisions; btShockPredictor.h), so the plugin
// solves it with both bodies free, as Bullet does, and the heavy box sinks through (stock SI too).
// Gravity is the only source of energy: the kinetic energy may never
// exceed the potential energy given up. Before the position correction followed the velocity
// step's rule, it held the heavy box up by its position while the row let its velocity fall:
// 8.2e3 J of kinetic energy with the column at rest in position (docs/design.md, section 7).
TEST(Conservation, AHeavyBoxOnALightOneGainsNoEnergyBeyondWhatItsFallReleases)
{
	const EnergyExcess e = measureEnergyExcess({btScalar(1), btScalar(1e5)}, "1e5:1 pair");
	// Round-off: 1e-6 of the heavy box's weight over the 2 s fall of one box height.
	const btScalar bound = btScalar(1e-6) * btScalar(1e5) * kG * btScalar(0.5) + btScalar(1e-3);
	EXPECT_LE(e.excess[1], bound) << e.names[1];
	EXPECT_LE(e.excess[2], bound) << e.names[2];
}

// A 1e7 kg box on an 18 g box (s = 5.6e8): the predictor once took a free side whose term was
// below 1e-7 of the row's for a zero-mass axis, skipped the row and fixated the position
// correction's, so the heavy box's velocity fell as g t while its position held: 1.9e9 J of kinetic
// energy with nothing released, in float and double (5.6e7 on 1 kg: 1.1e8 J). A free side that
// moves at all is now solved by its s: past the limit, both free, and the heavy box sinks through
// as under stock, its kinetic energy what the fall releases (docs/design.md, section 4.3).
TEST(Conservation, AVeryHeavyBoxOnALightOneGainsNoEnergyBeyondWhatItsFallReleases)
{
	const EnergyExcess e = measureEnergyExcess({btScalar(0.018), btScalar(1e7)}, "1e7 kg on 18 g");
	const btScalar bound = btScalar(1e-6) * btScalar(1e7) * kG * btScalar(0.5) + btScalar(1e-3);
	for (int m = 0; m < 3; ++m) EXPECT_TRUE(e.finite[m]) << e.names[m];
	EXPECT_LE(e.excess[1], bound) << e.names[1];
	EXPECT_LE(e.excess[2], bound) << e.names[2];
}

// Hostile world seed 87 without poison, as a column: 0.147 kg, 3,849 kg, 1.01 kg, 83 g and 609 t
// boxes on the floor. Every row above the lowest has s past the fixation limit in float (the 609 t
// box on the 83 g one: 7.3e6), so those rows are solved with both bodies free, as Bullet does; from
// zero impulses a few sweeps cannot carry 609 t through an 83 g box, so the heavy box's velocity
// fell as g t while the position correction held it up: 7.0e6 J of kinetic energy beyond the
// potential energy released within 2 s (world mode). Started from their points' last impulses, as
// a stock step starts them, those rows carry the load from step to step and the column gains
// nothing (docs/design.md, section 4.3). Stock SI in the same run for reference.
TEST(Conservation, AColumnWithRowsPastTheFixationLimitGainsNoEnergy)
{
	const std::vector<btScalar> masses = {btScalar(0.147), btScalar(3849), btScalar(1.01), btScalar(0.083), btScalar(6.09e5)};
	const EnergyExcess e = measureEnergyExcess(masses, "column past the fixation limit");
	for (int m = 0; m < 3; ++m) EXPECT_TRUE(e.finite[m]) << e.names[m];
	// Round-off: 1e-6 of the heavy box's weight over a fall of the column's height (2.5 m).
	const btScalar bound = btScalar(1e-6) * masses.back() * kG * btScalar(2.5) + btScalar(1e-3);
	EXPECT_LE(e.excess[1], bound) << e.names[1];
	EXPECT_LE(e.excess[2], bound) << e.names[2];
}
