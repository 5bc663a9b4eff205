// Conservation specs of the plugin's velocity step on the stacking scenes (docs/design.md), and a
// jointed toy on the pyramid of base 80 (at the end):
// the registry's tower, pyramid, wall and round tower, built as the demos build them, with the
// ground made frictionless before the first step (the bodies keep the scene's friction among
// themselves). Each structure is in equilibrium, so physics says: it stands, its horizontal
// momentum and its angular momentum about the vertical stay at their start values (nothing acts
// on it horizontally but its own contacts; bound 1e-6 of m g t, round-off), and it gains no
// energy (kinetic plus potential never above its start value, within round-off).
//
// Modes: stock SI (printed, not asserted: it does not conserve), the plugin in world and
// solver-only mode (asserted) and its classic order (momentum asserted). 60 Hz, 10 iterations, 5 s. Each test prints one line
//   ICE | <scene> | <mode> dp ... dL ... drift ... gain ... | ...
// before it asserts.

#include <BulletShockPropagation/btShockPropagationCommon.h>
#include <harness/Metrics.h>
#include <harness/Trial.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace
{
enum Mode
{
	kStock,
	kWorld,
	kSolver,
	kClassic,
	kNumModes
};
const char* kModeNames[kNumModes] = {"stock", "world", "solver", "classic"};

struct Outcome
{
	double momentum = 0;  // largest |horizontal momentum - start| (kg m/s)
	double angular = 0;   // largest |angular momentum about the vertical - start| (kg m^2/s)
	double drift = 0;     // largest body displacement from the start (m)
	double gain = 0;      // largest (kinetic + potential) - start (J)
	double bound = 0;     // 1e-6 m g t (kg m/s)
	double mass = 0;      // kg
};

harness::SolverSpec specOf(Mode mode)
{
	harness::SolverSpec s;
	s.iterations = 10;
	s.kind = mode == kStock ? harness::SolverKind::StockSI : mode == kSolver ? harness::SolverKind::ShockSolverOnly : harness::SolverKind::ShockWorld;
	s.settings.m_weightFeeling = mode != kClassic;
	return s;
}

struct Totals
{
	btVector3 momentum{0, 0, 0};
	double angular = 0, energy = 0, mass = 0;  // energy: kinetic plus potential above y = 0 (J)
};

Totals totals(const std::vector<btRigidBody*>& bodies, double g)
{
	Totals t;
	for (const btRigidBody* b : bodies)
	{
		if (!(b->getInvMass() > 0)) continue;
		const btScalar m = btScalar(1) / b->getInvMass();
		const btVector3 v = b->getLinearVelocity();
		const btVector3 spin = b->getInvInertiaTensorWorld().inverse() * b->getAngularVelocity();
		t.momentum += m * v;
		t.angular += double(spin.y() + b->getCenterOfMassPosition().cross(m * v).y());
		t.energy += double(m) * g * double(b->getCenterOfMassPosition().y());
		t.mass += double(m);
	}
	t.energy += harness::kineticEnergy(bodies);
	return t;
}

Outcome run(Mode mode, const std::string& scene, const std::vector<std::pair<std::string, double>>& params, double seconds)
{
	harness::Trial trial(specOf(mode), scene, params);
	btDiscreteDynamicsWorld& world = trial.simulation().world();
	for (int i = 0; i < world.getNumCollisionObjects(); ++i)
	{
		btCollisionObject* object = world.getCollisionObjectArray()[i];
		if (object->isStaticOrKinematicObject()) object->setFriction(0);
	}
	const double g = double(-world.getGravity().y());
	const Totals start = totals(trial.bodies(), g);
	Outcome out;
	out.mass = start.mass;
	const int steps = int(seconds * 60 + 0.5);
	for (int s = 0; s < steps; ++s)
	{
		trial.step();
		const Totals now = totals(trial.bodies(), g);
		btVector3 dp = now.momentum - start.momentum;
		dp.setY(0);
		out.momentum = std::max(out.momentum, double(dp.length()));
		out.angular = std::max(out.angular, std::abs(now.angular - start.angular));
		out.gain = std::max(out.gain, now.energy - start.energy);
	}
	out.drift = trial.maxDrift();
	out.bound = 1e-6 * start.mass * g * seconds;
	return out;
}

void report(const std::string& label, const Outcome* o)
{
	std::printf("ICE | %s", label.c_str());
	for (int m = 0; m < kNumModes; ++m)
		std::printf(" | %s dp %.2g kg m/s dL %.2g kg m^2/s drift %.3g cm gain %.2g J", kModeNames[m], o[m].momentum, o[m].angular,
					o[m].drift * 100, o[m].gain);
	std::printf(" | bound dp %.2g, %.0f kg\n", o[0].bound, o[0].mass);
}

/// classicStands: the classic order (no weight feeling) must hold it too, as the default does.
void expectConserved(const std::string& scene, const std::vector<std::pair<std::string, double>>& params, const std::string& label,
					 bool classicStands = false)
{
	const double seconds = 5;
	Outcome o[kNumModes];
	for (int m = 0; m < kNumModes; ++m) o[m] = run(Mode(m), scene, params, seconds);
	report(label, o);
	// Round-off of the energy: 1e-6 of the structure's weight times 1 m.
	const double energyBound = 1e-6 * o[0].mass * 9.81;
	for (Mode m : {kWorld, kSolver})
	{
		EXPECT_LE(o[m].momentum, o[m].bound) << kModeNames[m];
		EXPECT_LE(o[m].angular, o[m].bound) << kModeNames[m];
		EXPECT_LE(o[m].drift, 0.01) << kModeNames[m];  // it stands
		EXPECT_LE(o[m].gain, energyBound) << kModeNames[m];
	}
	EXPECT_LE(o[kClassic].momentum, o[kClassic].bound);
	if (!classicStands) return;
	EXPECT_LE(o[kClassic].drift, 0.01) << "classic";
	EXPECT_LE(o[kClassic].gain, energyBound) << "classic";
}
}  // namespace

// Tower of 20 boxes: stock SI crushes it (about 25 m of drift), the plugin holds it.
TEST(StructuresOnIce, TowerOf20KeepsItsMomentumAndStands) { expectConserved("tower", {{"n", 20}}, "tower of 20"); }

// Pyramid of base 12 (78 boxes): stock SI drifts about 1.7 cm, the plugin holds it.
TEST(StructuresOnIce, PyramidOfBase12KeepsItsMomentumAndStands) { expectConserved("pyramid", {{"base", 12}}, "pyramid of base 12"); }

// Pyramid of base 20 (210 boxes) and the wall: stock SI drifts 5.3 cm and 16.7 m. Before each
// predictor cycle was line searched on its own, their cycles diverged once the float residual sat
// at the convergence speed (1.0e-6, 3.4e-6, 1.2e-4 m/s over three cycles) and both gained
// energy (base 20: 6.8 m of drift, 1.5e3 J; the wall 13.9 m, 480 J; docs/design.md, section 4.7).
// The classic order holds both too since a fixated body on ice is fixated only in the directions
// its supports resist (btFixatedMobility.cpp); with every direction fixated it lost them (5.9 m
// and 13.5 m of drift, 1.4e3 and 650 J gained: the bottom row held still sideways under each
// cycle's squeeze from above, then pushed out by its delivery).
TEST(StructuresOnIce, PyramidOfBase20KeepsItsMomentumAndStands)
{
	expectConserved("pyramid", {{"base", 20}}, "pyramid of base 20", true);
}
TEST(StructuresOnIce, WallKeepsItsMomentumAndStands) { expectConserved("wall", {}, "wall", true); }

// The truth suite's resting structures whose stacks stand by statics alone (their ground
// friction is not what holds them): a harmonic stack at 0.85 of the book-stacking overhang, the
// loaded lintel on capped columns, the goal post of 2- and 4-box columns and the loaded plank on
// two thin posts (stock drifts 716, 4.4, 1.0 and 0.38 cm; the classic order loses the stack, the
// lintel and the plank: 10 m, 5.3 m, 2.7 m).
TEST(StructuresOnIce, HarmonicStackKeepsItsMomentumAndStands) { expectConserved("harmonic_stack", {}, "harmonic stack 0.85"); }
TEST(StructuresOnIce, LoadedLintelKeepsItsMomentumAndStands) { expectConserved("loaded_lintel", {}, "loaded lintel"); }
TEST(StructuresOnIce, DoorKeepsItsMomentumAndStands) { expectConserved("door", {}, "door"); }
TEST(StructuresOnIce, LoadedPlankKeepsItsMomentumAndStands) { expectConserved("loaded_plank", {}, "loaded plank"); }

// Known failure of the plugin (docs/design.md, known limits): run it
// with --gtest_also_run_disabled_tests. The round tower (20 rings of 16 bricks, each ring turned
// by half a brick), float: world mode 28 cm of drift and 8 J gained, solver-only 9.3 m and
// 390 J (stock 43 cm, 0 J).
TEST(StructuresOnIce, DISABLED_RoundTowerKeepsItsMomentumAndStands) { expectConserved("round_tower", {}, "round tower"); }

// A jointed toy changes nothing far away (issue 36). Two 50 g cubes of 10 cm joined by a
// point-to-point joint are dropped from 5 cm onto the apex of the pyramid of base 80 (3,240 boxes,
// on its ordinary rough ground). Physics: a 0.1 kg load on a pyramid in equilibrium leaves it
// standing. The layered step's rule for "driven" supports (D32) flooded through every contact from
// the jointed cubes and treated the whole pile as driven: it moved 38 cm at 1.47 s, while the same
// cubes without the joint left it at 0.02 cm. The converging step has no such rule: asserted here
// with the joint, in world and solver-only mode, for 2 s (measured: 2.7e-6 and 2.4e-6 cm; the
// unjointed cubes 5.4e-6 cm).
namespace
{
/// Largest displacement of the pyramid's boxes (m) over 2 s with the toy dropped on its apex.
double pyramidDriftUnderToy(Mode mode)
{
	harness::Trial trial(specOf(mode), "pyramid", {{"base", 80}});
	const btRigidBody* apex = trial.bodies().front();
	for (const btRigidBody* b : trial.bodies())
		if (b->getCenterOfMassPosition().y() > apex->getCenterOfMassPosition().y()) apex = b;
	btVector3 lo, hi;
	apex->getAabb(lo, hi);
	// The toy joins the scene (which owns and removes it) after the trial took its bodies, so the
	// drift is the pyramid's. Combined friction 0.25 per scene pair: each cube 0.5, Bullet's default.
	const btVector3 apexTop(apex->getCenterOfMassPosition().x(), hi.y(), apex->getCenterOfMassPosition().z());
	btRigidBody* toy[2];
	for (int i = 0; i < 2; ++i)
	{
		btTransform t;
		t.setIdentity();
		t.setOrigin(apexTop + btVector3(btScalar(i == 0 ? -0.06 : 0.06), btScalar(0.1), 0));
		toy[i] = trial.scene().addBody(new btBoxShape(btVector3(0.05f, 0.05f, 0.05f)), btScalar(0.05), t, btScalar(0.25));
	}
	trial.scene().addConstraint(new btPoint2PointConstraint(*toy[0], *toy[1], btVector3(btScalar(0.06), 0, 0), btVector3(btScalar(-0.06), 0, 0)));
	trial.run(2.0);
	for (const btRigidBody* b : toy) EXPECT_GT(double(b->getCenterOfMassPosition().y()), double(lo.y())) << "the toy rests on the apex";
	return trial.maxDrift();
}
}  // namespace

TEST(JointedToy, OnTheLargePyramidChangesNothing)
{
	const double world = pyramidDriftUnderToy(kWorld);
	const double solver = pyramidDriftUnderToy(kSolver);
	std::printf("TOY | pyramid of base 80 under a jointed toy, largest drift in 2 s | world %.3g cm | solver %.3g cm\n", world * 100, solver * 100);
	EXPECT_LE(world, 0.01) << "world mode";
	EXPECT_LE(solver, 0.01) << "solver-only mode";
}
