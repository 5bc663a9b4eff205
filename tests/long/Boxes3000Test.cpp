// BenchmarkDemo's "3000 boxes" at full size (registry "boxes_3000": 8 x 8 columns of 47 cubes of
// 2 m, each layer 0.35 m further out than the one below) falls with stock's timing (issue 39). Every
// column must topple as soon as it exists (statics: from 5 boxes above a box the column's centre
// of mass overhangs it), so the heights of the boxes over time are what stock gets right: the
// plugin's boxes above 20 m and above 50 m at 2, 4 and 6 s are compared with stock's in the same
// test, as a share of the 3,008 boxes. Long (ctest -L long): about 40 s of stepping per plugin mode.
//   build/float/tests/bsp_long_tests --gtest_filter=Boxes3000.*
#include <harness/Trial.h>

#include <gtest/gtest.h>

#include <cstdio>

namespace
{
struct Heights
{
	int above20[3] = {0, 0, 0};  // at 2, 4, 6 s
	int above50[3] = {0, 0, 0};
	int bodies = 0;
};

Heights run(harness::SolverKind kind)
{
	harness::SolverSpec spec;
	spec.kind = kind;
	spec.iterations = 5;  // BenchmarkDemo's own m_numIterations
	harness::Trial trial(spec, "boxes_3000");
	Heights h;
	h.bodies = int(trial.bodies().size());
	for (int mark = 0; mark < 3; ++mark)
	{
		trial.run(2.0);
		for (const btRigidBody* b : trial.bodies())
		{
			const double y = double(b->getCenterOfMassPosition().y());
			h.above20[mark] += y > 20;
			h.above50[mark] += y > 50;
		}
	}
	return h;
}

void print(const char* name, const Heights& h)
{
	std::printf("BOXES3000 | %s | above 20 m at 2/4/6 s: %d %d %d | above 50 m: %d %d %d (of %d)\n", name, h.above20[0], h.above20[1], h.above20[2],
				h.above50[0], h.above50[1], h.above50[2], h.bodies);
}
}  // namespace

// The plugin's count above each height at each mark is at most stock's plus 20% of the boxes that
// start above it (issue 39: "height of the top boxes at 2, 4 and 6 s within stock's + 20%").
// Measured before the converging step (issue 39): at 4 s stock 1,138 above 20 m and 256 above 50
// m, the plugin 2,304 and 1,278; at 6 s stock none above 20 m, the plugin 2,086. Measured now
// (float, above 20 m / above 50 m at 2, 4, 6 s): stock 2291 1164 0 / 1536 256 0; world 2368 1620 0
// / 1536 427 0; solver-only 2368 1288 0 / 1536 256 0: every column down by 6 s as under stock, world
// mode's collapse a little behind stock's at 4 s.
TEST(Boxes3000, LeaningColumnsFallWithStocksTiming)
{
	const Heights stock = run(harness::SolverKind::StockSI);
	const Heights world = run(harness::SolverKind::ShockWorld);
	const Heights solver = run(harness::SolverKind::ShockSolverOnly);
	print("stock", stock);
	print("world", world);
	print("solver", solver);
	int start20 = 0, start50 = 0;
	{
		harness::SolverSpec spec;
		harness::Trial trial(spec, "boxes_3000");
		for (const btRigidBody* b : trial.bodies())
		{
			start20 += double(b->getCenterOfMassPosition().y()) > 20;
			start50 += double(b->getCenterOfMassPosition().y()) > 50;
		}
	}
	for (int mark = 0; mark < 3; ++mark)
		for (const Heights* h : {&world, &solver})
		{
			const char* mode = h == &world ? "world" : "solver-only";
			EXPECT_LE(h->above20[mark], stock.above20[mark] + 0.2 * start20) << mode << ", above 20 m at " << 2 * (mark + 1) << " s";
			EXPECT_LE(h->above50[mark], stock.above50[mark] + 0.2 * start50) << mode << ", above 50 m at " << 2 * (mark + 1) << " s";
		}
}
