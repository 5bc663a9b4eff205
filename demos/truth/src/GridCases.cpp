// The shape grid as truth cases (include/truth/GridCases.h). Each case restates one cell of
// tests/truth/ShapeGridTest.cpp or tests/truth/PushedGridTest.cpp; the expected values come from
// statics and Coulomb friction (measurePushedStack computes (F - mu W) / M), never from a solver.
#include <truth/GridCases.h>

#include <harness/Trial.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace truth
{
namespace
{
constexpr double kTogether = 0.01;      // m: "within 1 cm", "apart < 1 cm", "at rest"
constexpr int kColumnSteps = 600;       // 10 s at 60 Hz (harness::Trial's default time step)
constexpr double kSlides = 1.4, kStays = 0.6;  // the push in units of mu W
constexpr double kOffTheEdge = 1.0;     // m, a column's offset from the middle of a table top 0.8 m wide each way
constexpr int kFallSteps = 180;         // 3 s

struct Kind
{
	int id;
	const char* name;
};
// The names of the ctest grid's cells (ShapeGridTest's and PushedGridTest's cellName).
const Kind kShapes[] = {{0, "box"}, {1, "hull"}, {3, "prism"}, {4, "cylinder"}, {5, "compound"}};
const Kind kGrounds[] = {{0, "onBox"}, {1, "onPlane"}, {2, "onMesh"}, {3, "onMeshEdges"}, {4, "onHeightfield"}};
const Kind kPlankShapes[] = {{0, "box"}, {1, "hull"}};
const Kind kRoundShapes[] = {{6, "capsule"}, {7, "sphere"}};
const char* kRoundWords[] = {"capsule lying on its side", "sphere"};
const char* kShapeWords[] = {"boxes", "hulls", "hulls with features", "hexagonal prisms", "cylinders", "compounds"};
const char* kGroundWords[] = {"a box", "a plane", "a triangle mesh", "a triangle mesh with internal-edge adjustment", "a heightfield"};

std::string format(const char* pattern, double a = 0, double b = 0, double c = 0, double d = 0, double e = 0)
{
	char buffer[320];
	std::snprintf(buffer, sizeof buffer, pattern, a, b, c, d, e);
	return buffer;
}

std::string cell(const Kind& shape, const Kind& ground) { return std::string(shape.name) + "_" + ground.name; }

}  // namespace

Verdict standsVerdict(const harness::SolverSpec& spec, const std::string& scene, const std::vector<std::pair<std::string, double>>& params,
					  const std::string& what)
{
	harness::Trial trial(spec, scene, params);
	for (int k = 0; k < kColumnSteps; ++k) trial.step();
	const harness::TrialSummary s = trial.summary();
	Verdict v;
	v.unit = "m";
	v.figure = s.maxDrift;
	v.expected = 0;
	v.pass = !s.nonFinite && s.maxDrift < kTogether;
	v.detail = what + format(", in equilibrium: must stand; largest drift %.4f m in 10 s (limit 0.01)", s.maxDrift);
	if (s.nonFinite) v.detail += "; non-finite state";
	v.msPerStep = s.msPerStep;
	return v;
}

Verdict columnStandsVerdict(const harness::SolverSpec& spec, int shape, int ground)
{
	return standsVerdict(spec, "shape_column", {{"shape", shape}, {"ground", ground}}, "column of 10");
}

Verdict roundOnBlockVerdict(const harness::SolverSpec& spec, int shape, int ground)
{
	return standsVerdict(spec, "round_on_block", {{"shape", shape}, {"ground", ground}}, "100 kg round body on a 1 kg box");
}

Verdict tableStackVerdict(const harness::SolverSpec& spec, int ground)
{
	return standsVerdict(spec, "table_stack", {{"ground", ground}}, "compound table carrying 5 boxes");
}

Verdict tableStackFallsVerdict(const harness::SolverSpec& spec, int ground)
{
	harness::Trial trial(spec, "table_stack", {{"ground", ground}, {"offset", kOffTheEdge}});
	const btRigidBody* top = trial.named("top");
	const double tableTop = trial.scene().facts.at("tableTop");
	for (int k = 0; k < kFallSteps; ++k) trial.step();
	const harness::TrialSummary s = trial.summary();
	Verdict v;
	v.unit = "m";
	v.figure = double(top->getCenterOfMassPosition().y()) - tableTop;
	v.expected = 0;
	v.pass = !s.nonFinite && v.figure < 0;
	v.detail = format("column of 5 boxes 1 m off the middle of a table top 0.8 m wide each way: must fall off; top box's centre %.3f m "
					  "above the table top after 3 s (must be below)",
					  v.figure);
	if (s.nonFinite) v.detail += "; non-finite state";
	v.msPerStep = s.msPerStep;
	return v;
}

Verdict plankCribVerdict(const harness::SolverSpec& spec, int shape, int ground)
{
	return standsVerdict(spec, "plank_crib", {{"shape", shape}, {"ground", ground}}, "crib of 10 layers of two planks");
}

const std::vector<TruthCase>& gridCases()
{
	static const std::vector<TruthCase> cases = [] {
		std::vector<TruthCase> all;
		for (const Kind& shape : kShapes)
		{
			for (const Kind& ground : kGrounds)
			{
				TruthCase c;
				c.name = "Column_" + cell(shape, ground) + "_Stands";
				c.group = "grid_column";
				c.statement = std::string("a column of 10 ") + kShapeWords[shape.id] + " (1 m wide, 0.5 m tall, 1 kg, mu 0.6) on " +
							  kGroundWords[ground.id] + " is in equilibrium and stands: every body within 1 cm for 10 s";
				const int s = shape.id, g = ground.id;
				c.run = [s, g](const harness::SolverSpec& spec) { return columnStandsVerdict(spec, s, g); };
				all.push_back(c);
			}
		}
		for (const Kind& round : kRoundShapes)
		{
			for (const Kind& ground : kGrounds)
			{
				TruthCase c;
				c.name = "RoundOnBlock_" + cell(round, ground) + "_Stands";
				c.group = "grid_round";
				c.statement = std::string("a 100 kg ") + kRoundWords[round.id - 6] + " (radius 0.25 m, mu 0.6) resting on the middle of a 1 kg box on " +
							  kGroundWords[ground.id] + " is in equilibrium and stands: both bodies within 1 cm for 10 s";
				const int s = round.id, g = ground.id;
				c.run = [s, g](const harness::SolverSpec& spec) { return roundOnBlockVerdict(spec, s, g); };
				all.push_back(c);
			}
		}
		for (const Kind& ground : kGrounds)
		{
			TruthCase c;
			c.name = std::string("TableStack_") + ground.name + "_Stands";
			c.group = "grid_structure";
			c.statement = std::string("a 10 kg table made as one compound body (top and four legs) carrying a column of 5 boxes (1 kg) on ") +
						  kGroundWords[ground.id] + " is in equilibrium and stands: every body within 1 cm for 10 s";
			const int g = ground.id;
			c.run = [g](const harness::SolverSpec& spec) { return tableStackVerdict(spec, g); };
			all.push_back(c);
		}
		for (const Kind& ground : kGrounds)
		{
			TruthCase c;
			c.name = std::string("TableStack_") + ground.name + "_FallsOffTheEdge";
			c.group = "grid_structure";
			c.statement = std::string("the same table on ") + kGroundWords[ground.id] +
						  " with its column of 5 boxes 1 m off the middle (its centre of mass beyond the top's edge at 0.8 m): the "
						  "column falls off, the top box below the table top within 3 s";
			const int g = ground.id;
			c.run = [g](const harness::SolverSpec& spec) { return tableStackFallsVerdict(spec, g); };
			all.push_back(c);
		}
		for (const Kind& plank : kPlankShapes)
		{
			for (const Kind& ground : kGrounds)
			{
				TruthCase c;
				c.name = "PlankCrib_" + cell(plank, ground) + "_Stands";
				c.group = "grid_structure";
				c.statement = std::string("a crib of 10 layers of two interlocking planks (") + kShapeWords[plank.id] +
							  ", 3 x 0.3 x 0.3 m, 5 kg, each layer turned 90 degrees) on " + kGroundWords[ground.id] +
							  " is in equilibrium and stands: every plank within 1 cm for 10 s";
				const int s = plank.id, g = ground.id;
				c.run = [s, g](const harness::SolverSpec& spec) { return plankCribVerdict(spec, s, g); };
				all.push_back(c);
			}
		}
		for (const double fraction : {kSlides, kStays})
		{
			const bool slides = fraction > 1;
			for (const Kind& shape : kShapes)
			{
				for (const Kind& ground : kGrounds)
				{
					TruthCase c;
					c.name = "Pushed_" + cell(shape, ground) + (slides ? "_F140_SlidesTogether" : "_F060_AtRest");
					c.group = slides ? "grid_slides" : "grid_stays";
					c.statement = std::string("5 stacked ") + kShapeWords[shape.id] + " (1 kg, ground mu 0.5, body-body mu 1) on " +
								  kGroundWords[ground.id] + " pushed at the bottom with " +
								  (slides ? "1.4 mu W slide as one at (F - mu W) / M within 10%, no body more than 1 cm from where the "
											"bottom one carries it"
										  : "0.6 mu W stay at rest: no body drifts 1 cm (Coulomb: F <= mu W)");
					const int s = shape.id, g = ground.id;
					c.run = [s, g, fraction](const harness::SolverSpec& spec) { return pushedStackVerdict(spec, fraction, {{"shape", s}, {"ground", g}}); };
					all.push_back(c);
				}
			}
		}
		return all;
	}();
	return cases;
}
}  // namespace truth
