// The statics and friction half of the truth suite: stacks that must stand or topple by statics,
// stacks pushed or put on a ramp (Coulomb friction), the ground reaction of large structures, and
// support forces by the lever rule. Every expected value is computed here from physics; none comes
// from a solver's output. Conditions: 60 Hz, float, sleeping off (every registry scene disables
// deactivation), g = 9.81 m/s^2.
#include <truth/TruthCase.h>

#include <harness/Metrics.h>
#include <harness/Trial.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace truth
{
namespace
{
using Overrides = std::vector<std::pair<std::string, double>>;

constexpr double kGravity = 9.81;              // m/s^2, harness::Simulation's default
constexpr double kFrameRate = 60;              // Hz, harness::Trial's default time step
constexpr double kRestToleranceMeters = 0.01;  // "at rest" / "together": within 1 cm
constexpr double kPi = 3.14159265358979323846;

int stepsFor(double seconds) { return int(seconds * kFrameRate + 0.5); }

std::string format(const char* pattern, double a = 0, double b = 0, double c = 0, double d = 0, double e = 0)
{
	char buffer[320];
	std::snprintf(buffer, sizeof buffer, pattern, a, b, c, d, e);
	return buffer;
}

Verdict finished(Verdict v, const harness::Trial& trial)
{
	v.msPerStep = trial.summary().msPerStep;
	return v;
}

double massOf(const btRigidBody* body) { return body->getInvMass() > 0 ? 1.0 / body->getInvMass() : 0.0; }

/// Time step of the manifolds' impulses: the frame's last sub-step.
double impulseTimeStep(harness::Trial& trial)
{
	return trial.simulation().timeStep() / trial.simulation().spec().substeps;
}

/// Least-squares acceleration of x(t) = x0 + v0 t + a t^2 / 2 over the samples (t, x).
double fittedAcceleration(const std::vector<double>& t, const std::vector<double>& x)
{
	const size_t n = t.size();
	if (n < 3) return std::numeric_limits<double>::quiet_NaN();
	double mean = 0;
	for (double ti : t) mean += ti / double(n);
	// Normal equations of the basis 1, s, s^2 / 2 with s = t - mean (well conditioned).
	double m[3][4] = {};
	for (size_t i = 0; i < n; ++i)
	{
		const double s = t[i] - mean;
		const double basis[3] = {1, s, s * s / 2};
		for (int r = 0; r < 3; ++r)
		{
			for (int c = 0; c < 3; ++c) m[r][c] += basis[r] * basis[c];
			m[r][3] += basis[r] * x[i];
		}
	}
	for (int p = 0; p < 3; ++p)  // Gauss-Jordan; the matrix is symmetric positive definite
	{
		for (int r = 0; r < 3; ++r)
		{
			if (r == p) continue;
			const double factor = m[r][p] / m[p][p];
			for (int c = p; c < 4; ++c) m[r][c] -= factor * m[p][c];
		}
	}
	return m[2][3] / m[2][2];
}

/// Largest displacement of any body relative to the displacement of `reference` (m): how far the
/// bodies have moved apart from the rigid motion `reference` makes.
double largestRelativeDisplacement(const std::vector<btRigidBody*>& bodies, const std::vector<btVector3>& start,
								   const btRigidBody* reference, const btVector3& referenceStart)
{
	const btVector3 moved = reference->getCenterOfMassPosition() - referenceStart;
	double largest = 0;
	for (size_t i = 0; i < bodies.size(); ++i)
		largest = std::max(largest, double((bodies[i]->getCenterOfMassPosition() - start[i] - moved).length()));
	return largest;
}

std::vector<btVector3> positions(const std::vector<btRigidBody*>& bodies)
{
	std::vector<btVector3> p;
	for (const btRigidBody* b : bodies) p.push_back(b->getCenterOfMassPosition());
	return p;
}

// ---------------------------------------------------------------------------------------------------
// Stand or fall: one verdict for every "topple" case. Stands: every body within 1 cm of its start
// after `seconds`. Falls: the top body's height drops by more than `edge` within `seconds`.

Verdict standOrFall(const harness::SolverSpec& spec, const std::string& scene, const Overrides& overrides,
					bool mustStand, double edge, double seconds, const std::string& why)
{
	harness::Trial trial(spec, scene, overrides);
	const btRigidBody* top = trial.scene().named("top");
	const double topStartY = top->getCenterOfMassPosition().y();
	double largestDrop = 0;
	double fellAt = -1;
	for (int k = 0; k < stepsFor(seconds); ++k)
	{
		trial.step();
		largestDrop = std::max(largestDrop, topStartY - top->getCenterOfMassPosition().y());
		if (!mustStand && largestDrop > edge)
		{
			fellAt = trial.simulation().time();
			break;  // verdict reached
		}
		if (mustStand && trial.drift().maxDrift() > kRestToleranceMeters) break;  // verdict reached
	}
	const harness::TrialSummary s = trial.summary();
	Verdict v;
	v.unit = "m";
	if (mustStand)
	{
		v.pass = s.standing;
		v.figure = s.maxDrift;
		v.expected = 0;
		v.detail = why + format(": must stand; largest drift %.4f m (limit 0.01)", s.maxDrift) +
				   (s.standing ? format(" over %.1f s", seconds) : format(", moved 1 cm at %.2f s", s.collapseTime));
	}
	else
	{
		v.pass = fellAt >= 0 && !s.nonFinite;
		v.figure = largestDrop;
		v.expected = edge;
		v.detail = why + format(": must fall; top cube dropped %.3f m (must exceed one edge, %.3f m)", largestDrop, edge) +
				   (fellAt >= 0 ? format(" by %.2f s", fellAt) : format(" in %.1f s", seconds));
	}
	if (s.nonFinite) v.detail += "; non-finite state";
	return finished(v, trial);
}

// Offset (staircase) stacks. n cubes of edge a, cube k (0 = bottom) at x = k d a. The cubes above cube
// k have their centre of mass at the mean of their x, d a ((k+1) + (n-1)) / 2 = d a (n + k) / 2, which is
// d a (n - k) / 2 past cube k's centre; they stand on cube k iff that is within its half width a / 2,
// i.e. d (n - k) <= 1. The worst support is the bottom cube (k = 0): the stack stands iff d n <= 1.
void addOffsetStacks(std::vector<TruthCase>& cases)
{
	struct Row
	{
		double d;
		int n;
	};
	// d n = 0.6, 0.8, 0.6 and 0.9 (stand); 1.2, 1.2, 1.2 and 1.35 (fall). For d = 0.45 the only standing
	// stack is n = 2 (0.9: the top cube's centre 2.5 cm inside the edge), so that is the one used.
	const Row rows[] = {{0.1, 6}, {0.1, 12}, {0.2, 4}, {0.2, 6}, {0.3, 2}, {0.3, 4}, {0.45, 2}, {0.45, 3}};
	for (const Row& r : rows)
	{
		const bool stands = r.d * r.n <= 1;
		const int percent = int(r.d * 100 + 0.5);
		TruthCase c;
		c.name = "OffsetStack_d" + std::to_string(percent) + "_n" + std::to_string(r.n) + (stands ? "_Stands" : "_Falls");
		c.group = "topple";
		c.statement = format("%.0f cubes each shifted %.2f edge past the one below (d n = %.2f): ", r.n, r.d, r.d * r.n) +
					  "a staircase stands iff d n <= 1 (the cubes above the bottom one have their COM d n a / 2 past its centre)";
		const double edge = 0.5;  // m, leaning_tower's default cube
		c.run = [r, stands, edge](const harness::SolverSpec& spec) {
			return standOrFall(spec, "leaning_tower", {{"n", r.n}, {"shift", r.d}, {"size", edge}}, stands, edge, 5.0,
							   format("d n = %.2f", r.d * r.n));
		};
		cases.push_back(c);
	}
}

// Harmonic (book-stacking) overhang, scaled: every sub-stack's COM is scale * a / 2 past its support's
// centre (truth/harmonic_stack), so it stands iff scale <= 1.
void addHarmonicStacks(std::vector<TruthCase>& cases)
{
	const int n = 6;
	const double edge = 0.5;  // m
	for (double scale : {0.85, 1.15})
	{
		const bool stands = scale <= 1;
		TruthCase c;
		c.name = std::string("HarmonicStack_s") + (stands ? "085_Stands" : "115_Falls");
		c.group = "topple";
		c.statement = format("6 cubes with %.2f times the harmonic overhang a / (2k): ", scale) +
					  "stands iff the scale is <= 1 (every sub-stack's COM is scale * a / 2 past its support's centre)";
		c.run = [=](const harness::SolverSpec& spec) {
			return standOrFall(spec, "harmonic_stack", {{"n", n}, {"scale", scale}, {"size", edge}}, stands, edge, 5.0,
							   format("scale %.2f", scale));
		};
		cases.push_back(c);
	}
}

// ---------------------------------------------------------------------------------------------------
// Friction.

/// A stack that must slide as one: its acceleration within 10% of `expected` and no box more than
/// kRestToleranceMeters from where the bottom box carries it.
void slidesTogether(Verdict& v, double a, double expected, double apart, bool nonFinite)
{
	v.unit = "m/s^2";
	v.figure = a;
	v.expected = expected;
	const bool rate = std::fabs(a - expected) <= 0.1 * expected;
	const bool together = apart < kRestToleranceMeters;
	v.pass = rate && together && !nonFinite;
}

// Pushed stack (truth/pushed_stack): 5 boxes of 1 kg, 1 x 0.5 x 1 m; box-ground mu = 0.5 (ground friction
// 0.5, box friction 1: Bullet multiplies), box-box mu = 1. A horizontal force F on the bottom box only.
// Coulomb: the stack stays at rest iff F <= mu W (W = total weight; the ground is the only resistance).
// Above that it slides as one body at a = (F - mu W) / M iff each interface can hold the boxes above: the
// bottom box must push the 4 boxes above with 4 m a, against a limit of 1.0 * 4 m g, so it holds while
// a < g (here a = 0.4 mu g = 0.2 g). The boxes above stay upright too: their inertia at their COM 1 m
// above the interface moves the normal force's centre back by a / g * 1 m = 0.2 m, within the 0.5 m
// half width.
constexpr double kPushGroundMu = 0.5;
constexpr double kPushSlideSeconds = 2.0;  // s, measured when it slides
constexpr double kPushRestSeconds = 3.0;   // s, measured when it must stay at rest


// Stack on a ramp (truth/ramp_stack): 3 boxes of 1 kg, 1 x 0.5 x 1 m, on a 20 degree ramp; box-ramp mu
// (ramp friction mu, box friction 1) and box-box mu = 1. Coulomb: the stack sticks iff mu >= tan(20 deg)
// = 0.364; otherwise it slides as one body at g (sin a - mu cos a) (1.511 m/s^2 at mu = 0.2), since the
// boxes above need only tan(a) = 0.36 (sticking) or mu = 0.2 (sliding together) of friction from the
// box below, against 1. Tipping: the stack's COM is 0.75 m above the ramp, its normal force centre moves
// by at most 0.75 tan(a) = 0.27 m, within the 0.5 m half width.
constexpr double kRampAngleDeg = 20;

Verdict rampStack(const harness::SolverSpec& spec, double mu)
{
	harness::Trial trial(spec, "ramp_stack", {{"angleDeg", kRampAngleDeg}, {"n", 3}, {"rampMu", mu}, {"boxMu", 1.0}});
	const double angle = kRampAngleDeg * kPi / 180;
	const bool sticks = mu >= std::tan(angle);
	const std::vector<btRigidBody*>& boxes = trial.bodies();
	btRigidBody* bottom = trial.scene().named("bottom");
	const btVector3 downSlope(btScalar(std::cos(angle)), btScalar(-std::sin(angle)), 0);
	const double seconds = sticks ? 5.0 : 2.0;
	const std::vector<btVector3> start = positions(boxes);
	const btVector3 bottomStart = bottom->getCenterOfMassPosition();
	std::vector<double> t, x;
	double apart = 0;
	for (int k = 0; k < stepsFor(seconds); ++k)
	{
		trial.step();
		const double time = trial.simulation().time();
		apart = std::max(apart, largestRelativeDisplacement(boxes, start, bottom, bottomStart));
		if (time >= 0.25)
		{
			t.push_back(time);
			x.push_back((bottom->getCenterOfMassPosition() - bottomStart).dot(downSlope));
		}
	}
	const harness::TrialSummary s = trial.summary();
	Verdict v;
	if (sticks)
	{
		v.unit = "m";
		v.figure = s.maxDrift;
		v.expected = 0;
		v.pass = s.maxDrift < kRestToleranceMeters && !s.nonFinite;
		v.detail = format("mu = %.2f >= tan(%.0f deg) = %.3f: must stick; largest drift %.4f m in %.0f s (limit 0.01)",
						  mu, kRampAngleDeg, std::tan(angle), s.maxDrift, seconds);
	}
	else
	{
		const double expected = kGravity * (std::sin(angle) - mu * std::cos(angle));
		const double a = fittedAcceleration(t, x);
		slidesTogether(v, a, expected, apart, s.nonFinite);
		v.detail = format("mu = %.2f < tan(20 deg): a = %.3f m/s^2 against g (sin a - mu cos a) = %.3f (within 10%%); boxes apart by %.4f m (limit 0.01)",
						  mu, a, expected, apart);
	}
	if (s.nonFinite) v.detail += "; non-finite state";
	return finished(v, trial);
}

void addFrictionCases(std::vector<TruthCase>& cases)
{
	for (double fraction : {0.6, 1.4})
	{
		const bool slides = fraction > 1;
		TruthCase c;
		c.name = slides ? "PushedStack_F140_SlidesTogether" : "PushedStack_F060_AtRest";
		c.group = "friction";
		c.statement = slides ? "5 boxes pushed at the bottom with 1.4 mu W slide as one at (F - mu W) / M (box-box mu 1 holds them together)"
							 : "5 boxes pushed at the bottom with 0.6 mu W stay at rest (Coulomb: F <= mu W)";
		c.run = [fraction](const harness::SolverSpec& spec) { return pushedStackVerdict(spec, fraction); };
		cases.push_back(c);
	}
	for (double mu : {0.5, 0.2})
	{
		const bool sticks = mu >= std::tan(kRampAngleDeg * kPi / 180);
		TruthCase c;
		c.name = sticks ? "RampStack_mu050_Sticks" : "RampStack_mu020_SlidesTogether";
		c.group = "friction";
		c.statement = sticks ? "3 boxes on a 20 deg ramp with mu 0.5 > tan 20 deg stick (Coulomb)"
							 : "3 boxes on a 20 deg ramp with mu 0.2 < tan 20 deg slide as one at g (sin a - mu cos a)";
		c.run = [mu](const harness::SolverSpec& spec) { return rampStack(spec, mu); };
		cases.push_back(c);
	}
}

// ---------------------------------------------------------------------------------------------------
// Statics: a standing structure at rest pushes on the ground with exactly its weight (sum of vertical
// forces on the structure = 0). Measured as the ground's vertical contact impulse / dt over total weight,
// averaged over the last second of 3 s (harness::Trial's groundOverWeight), and required within 5% while
// the structure still stands (every body within 1 cm): a collapsed heap also weighs its weight, which
// says nothing about the structure.

Verdict groundReaction(const harness::SolverSpec& spec, const std::string& scene, const Overrides& overrides, bool tooLargeForDantzig)
{
	Verdict v;
	v.unit = "-";
	v.expected = 1;
	if (tooLargeForDantzig && spec.kind == harness::SolverKind::MLCPDantzig)
	{
		v.figure = std::numeric_limits<double>::quiet_NaN();
		v.detail = "skipped: too large for Dantzig";
		return v;
	}
	harness::Trial trial(spec, scene, overrides);
	for (int k = 0; k < stepsFor(3.0); ++k) trial.step();
	const harness::TrialSummary s = trial.summary();
	v.figure = s.groundOverWeightLastSecond;
	v.pass = std::fabs(s.groundOverWeightLastSecond - 1) <= 0.05 && s.standing;
	v.detail = format("ground reaction / weight %.3f over the last second (1 within 5%%); largest drift %.4f m", s.groundOverWeightLastSecond, s.maxDrift) +
			   (s.standing ? std::string(", standing") : format(", moved 1 cm at %.2f s", s.collapseTime));
	if (s.nonFinite) v.detail += "; non-finite state";
	return finished(v, trial);
}

void addGroundReactionCases(std::vector<TruthCase>& cases)
{
	struct Row
	{
		const char* name;
		const char* scene;
		Overrides overrides;
		const char* what;
		bool tooLargeForDantzig;
	};
	const std::vector<Row> rows = {
		{"GroundReaction_Tower20", "tower", {{"n", 20}}, "20-box tower", false},
		{"GroundReaction_Tower40", "tower", {{"n", 40}}, "40-box tower", false},
		{"GroundReaction_Pyramid30", "pyramid", {{"base", 30}}, "pyramid of base 30 (465 boxes)", true},
		{"GroundReaction_Wall", "wall", {}, "200-piece wall", true},
		{"GroundReaction_RoundTower", "round_tower", {}, "320-brick round tower", true},
	};
	for (const Row& r : rows)
	{
		TruthCase c;
		c.name = r.name;
		c.group = "statics";
		c.statement = std::string("the ") + r.what + " at rest: ground reaction = total weight (within 5%), still standing";
		const std::string scene = r.scene;
		const Overrides overrides = r.overrides;
		const bool skip = r.tooLargeForDantzig;
		c.run = [scene, overrides, skip](const harness::SolverSpec& spec) { return groundReaction(spec, scene, overrides, skip); };
		cases.push_back(c);
	}
}

// ---------------------------------------------------------------------------------------------------
// Lever rule: a beam of weight W_b centred between two point-like supports at -+span/2, with a load W_l
// at `offset` right of centre: moments about each support give
//   right = W_b / 2 + W_l (1/2 + offset / span),   left = W_b / 2 + W_l (1/2 - offset / span).
// Both scenes use thin supports (0.1 m along x, 3-4% of the span) so the split is determinate to that
// accuracy. Each support's vertical force on the beam: the manifolds' applied impulses / dt
// (harness::supportForce), averaged over the last second of 3 s; each within 10%.

Verdict leverRule(const harness::SolverSpec& spec, const std::string& scene, const char* beamName, const char* loadName,
				  const char* leftName, const char* rightName)
{
	harness::Trial trial(spec, scene);
	const scenes::Params& defaults = scenes::findScene(scene)->defaults;
	const double span = scenes::getParam(defaults, "span");      // m, between the support centres
	const double offset = scenes::getParam(defaults, "offset");  // m, load centre right of the beam centre
	const btRigidBody* beam = trial.scene().named(beamName);
	const btRigidBody* load = trial.scene().named(loadName);
	const btRigidBody* left = trial.scene().named(leftName);
	const btRigidBody* right = trial.scene().named(rightName);
	const double beamWeight = massOf(beam) * kGravity;
	const double loadWeight = massOf(load) * kGravity;
	const double expectedRight = beamWeight / 2 + loadWeight * (0.5 + offset / span);
	const double expectedLeft = beamWeight / 2 + loadWeight * (0.5 - offset / span);
	btDispatcher& dispatcher = *trial.simulation().world().getDispatcher();
	const int settle = stepsFor(2.0);
	const int average = stepsFor(1.0);
	double leftForce = 0;
	double rightForce = 0;
	for (int k = 0; k < settle + average; ++k)
	{
		trial.step();
		if (k < settle) continue;
		leftForce += harness::supportForce(dispatcher, beam, left, impulseTimeStep(trial)) / average;
		rightForce += harness::supportForce(dispatcher, beam, right, impulseTimeStep(trial)) / average;
	}
	const harness::TrialSummary s = trial.summary();
	Verdict v;
	v.unit = "N";
	v.figure = rightForce;
	v.expected = expectedRight;
	const double leftError = std::fabs(leftForce - expectedLeft) / expectedLeft;
	const double rightError = std::fabs(rightForce - expectedRight) / expectedRight;
	v.pass = leftError <= 0.1 && rightError <= 0.1 && !s.nonFinite;
	v.detail = format("right support %.2f N (lever rule %.2f), left %.2f N (lever rule %.2f), each within 10%%; largest drift %.4f m",
					  rightForce, expectedRight, leftForce, expectedLeft, s.maxDrift);
	if (s.nonFinite) v.detail += "; non-finite state";
	return finished(v, trial);
}

void addLeverCases(std::vector<TruthCase>& cases)
{
	{
		TruthCase c;
		c.name = "Lever_LoadedPlank";
		c.group = "lever";
		c.statement = "plank (2 kg) on two posts 3 m apart, 5 kg load 0.75 m right of centre: each post carries its lever-rule share of plank + load";
		// hard/loaded_plank defaults: span 3 m, offset 0.75 m, plank 2 kg, load 5 kg.
		c.run = [](const harness::SolverSpec& spec) {
			return leverRule(spec, "loaded_plank", "plank", "load", "leftSupport", "rightSupport");
		};
		cases.push_back(c);
	}
	{
		TruthCase c;
		c.name = "Lever_LoadedLintel";
		c.group = "lever";
		c.statement = "lintel (2 kg) on two capped columns 2.5 m apart, 5 kg load 0.6 m right of centre: each cap carries its lever-rule share of lintel + load";
		// truth/loaded_lintel defaults: span 2.5 m, offset 0.6 m, lintel 2 kg, load 5 kg.
		c.run = [](const harness::SolverSpec& spec) {
			return leverRule(spec, "loaded_lintel", "lintel", "load", "leftCap", "rightCap");
		};
		cases.push_back(c);
	}
}
}  // namespace

Verdict pushedStackVerdict(const harness::SolverSpec& spec, double capacityFraction, const std::vector<std::pair<std::string, double>>& sceneOverrides)
{
	const PushedStack p = measurePushedStack(spec, capacityFraction, sceneOverrides);
	const bool slides = capacityFraction > 1;
	Verdict v;
	if (!slides)
	{
		v.unit = "m";
		v.figure = p.maxDrift;
		v.expected = 0;
		v.pass = p.maxDrift < kRestToleranceMeters && !p.nonFinite;
		v.detail = format("F = %.2f mu W = %.2f N < mu W = %.2f N: must stay at rest; largest drift %.4f m in %.0f s (limit 0.01)",
						  capacityFraction, p.force, p.force / capacityFraction, p.maxDrift, kPushRestSeconds);
	}
	else
	{
		slidesTogether(v, p.acceleration, p.expected, p.apart, p.nonFinite);
		v.detail = format("F = %.2f mu W: a = %.3f m/s^2 against (F - mu W) / M = %.3f (within 10%%); bodies apart by %.4f m (limit 0.01)",
						  capacityFraction, p.acceleration, p.expected, p.apart);
	}
	if (p.nonFinite) v.detail += "; non-finite state";
	v.msPerStep = p.msPerStep;
	return v;
}

PushedStack measurePushedStack(const harness::SolverSpec& solver, double capacityFraction, const Overrides& sceneOverrides)
{
	Overrides overrides = {{"n", 5}, {"groundMu", kPushGroundMu}, {"boxMu", 1.0}};
	overrides.insert(overrides.end(), sceneOverrides.begin(), sceneOverrides.end());  // later entries win
	harness::Trial trial(solver, "pushed_stack", overrides);
	const std::vector<btRigidBody*>& boxes = trial.bodies();
	btRigidBody* bottom = trial.scene().named("bottom");
	double mass = 0;
	for (const btRigidBody* b : boxes) mass += massOf(b);
	const double weight = mass * kGravity;
	const double groundMu = trial.scene().facts.at("groundMu");  // kPushGroundMu unless overridden
	PushedStack p;
	p.force = capacityFraction * groundMu * weight;  // N, along +x
	const bool slides = capacityFraction > 1;
	p.expected = slides ? (p.force - groundMu * weight) / mass : 0;
	const std::vector<btVector3> start = positions(boxes);
	const btVector3 bottomStart = bottom->getCenterOfMassPosition();
	std::vector<double> t, x;
	for (int k = 0; k < stepsFor(slides ? kPushSlideSeconds : kPushRestSeconds); ++k)
	{
		bottom->applyCentralForce(btVector3(btScalar(p.force), 0, 0));  // Bullet clears forces every step
		trial.step();
		const double time = trial.simulation().time();
		p.apart = std::max(p.apart, largestRelativeDisplacement(boxes, start, bottom, bottomStart));
		if (time >= 0.25)
		{
			t.push_back(time);
			x.push_back(bottom->getCenterOfMassPosition().x() - bottomStart.x());
		}
	}
	p.acceleration = fittedAcceleration(t, x);
	const harness::TrialSummary s = trial.summary();
	p.maxDrift = s.maxDrift;
	p.nonFinite = s.nonFinite;
	p.msPerStep = s.msPerStep;
	return p;
}

void addStaticsCases(std::vector<TruthCase>& cases)
{
	addOffsetStacks(cases);
	addHarmonicStacks(cases);
	addFrictionCases(cases);
	addGroundReactionCases(cases);
	addLeverCases(cases);
}
}  // namespace truth
