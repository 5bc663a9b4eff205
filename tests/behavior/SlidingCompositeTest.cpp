// D23 (docs/design.md, section 4h; opt-in): a free body whose support friction is at its Coulomb
// limit and slips carries the inertia of the sub-stack resting on it.
//
// The law these tests assert is impulse and momentum, not the plugin's output: a stack that slides
// from rest down a ramp against kinetic friction has, after T seconds, the momentum
// M g (sin a - mu cos a) T down the slope, however its boxes share it. A layered solve that settles
// the boxes above before their base has felt them discards that momentum through its weight-pass
// guard.
#include "Fixture.h"

#include <BulletShockPropagation/btShockPropagationConstraintSolver.h>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
const double kGravity = 9.81;

struct Slide
{
	double momentumRatio = 0;  // the stack's momentum along the slide over the law's (mean over the run)
	long composites = 0;       // composites formed over the run
};

btVector3 totalMomentum(const std::vector<btRigidBody*>& bodies)
{
	btVector3 p(0, 0, 0);
	for (const btRigidBody* b : bodies) p += b->getLinearVelocity() / b->getInvMass();
	return p;
}

double totalMass(const std::vector<btRigidBody*>& bodies)
{
	double m = 0;
	for (const btRigidBody* b : bodies) m += 1.0 / b->getInvMass();
	return m;
}

/// Three 1 kg boxes on a 20 degree ramp with ramp mu 0.2 (< tan 20 deg: they slide as one).
Slide rampStack(const harness::SolverSpec& spec, double seconds)
{
	harness::Trial run(spec, "ramp_stack", {{"angleDeg", 20}, {"n", 3}, {"rampMu", 0.2}, {"boxMu", 1.0}});
	const double angle = 20 * M_PI / 180;
	const btVector3 down(btScalar(std::cos(angle)), btScalar(-std::sin(angle)), 0);
	Slide s;
	const int steps = int(std::lround(seconds * 60));
	const double rate = totalMass(run.bodies()) * kGravity * (std::sin(angle) - 0.2 * std::cos(angle));  // N
	for (int i = 0; i < steps; ++i)
	{
		run.step();
		if (const btShockPropagationConstraintSolver* solver = run.simulation().shockSolver())
			s.composites += solver->getStatistics().m_numSlidingComposites;
		const double t = (i + 1) / 60.0;
		if (t >= 0.25) s.momentumRatio += totalMomentum(run.bodies()).dot(down) / (rate * t) / double(steps - 14);
	}
	return s;
}

/// D23 is opt-in (btShockPropagationDiagnostics::m_slidingComposites).
harness::SolverSpec withComposites(harness::SolverSpec spec)
{
	spec.settings.m_diagnostics.m_slidingComposites = true;
	return spec;
}
}  // namespace

TEST(ConvergingStep, RampStackGainsTheMomentumOfKineticFriction)
{
	// Momentum down the slope over M g (sin a - mu cos a) t, averaged over 0.25-2 s, at the
	// defaults (the converging step), world and solver-only, 5, 10 and 20 iterations.
	for (const harness::SolverSpec& solver : {spec::shock(5), spec::shock(10), spec::shock(20), spec::shockSolverOnly(5), spec::shockSolverOnly(10), spec::shockSolverOnly(20)})
	{
		const Slide s = rampStack(solver, 2.0);
		EXPECT_NEAR(s.momentumRatio, 1.0, 0.02) << solver.label();
	}
}

TEST(SlidingComposites, RestingStacksFormNone)
{
	// A settled tower's supports do not slip: no composite, nothing changes for stacks at rest.
	harness::Trial tower(withComposites(spec::shock()), "tower", {{"n", 20}});
	tower.run(1.0);
	const long composites = spec::sumOverSteps(tower, 120, &btShockPropagationStatistics::m_numSlidingComposites);
	EXPECT_EQ(composites, 0);
	EXPECT_LT(tower.maxDrift(), harness::kStandingDriftMeters);
}
