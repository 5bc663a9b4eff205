// bsp_second_phase: the world's second phase (collision detection at t + dt, then correction;
// docs/design.md D4, issue 38) measured against the solver-only mode and stock SI, each case in
// the same run. Penetration is measured by a narrowphase of its own at the end of each step
// (btCollisionWorld::contactTest of every dynamic body), not from the step's manifolds: those
// hold the contacts of the step's start, and a contact that appeared during the step is in none.
//
//   bsp_second_phase [--pile-seconds S] [--seeds N] [--second-fraction F] [--rounds N]
//
// Rows: stock SI; solver-only; world with the second phase off (the world before issue 38, what
// m_secondCorrection = false gives); world with the depth refresh of before issue 38 (no
// detection); world with one round of detection and full correction; world (default: two
// rounds, the first removing 0.8 of each depth, the second all that is left).
#include <harness/Metrics.h>
#include <harness/Simulation.h>
#include <scenes/Registry.h>
#include <scenes/Scene.h>

#include <BulletShockPropagation/btShockPropagationCommon.h>
#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace
{
double gSecondFraction = -1;  // --second-fraction: the first rounds' share (default: the settings')
int gRounds = 0;               // --rounds: rounds of the default world row (default: the settings')

/// A static ground and a column of n 1 m cubes, each 10 micrometres into the one below (so that
/// the first step has its contacts), awake; more boxes by add(). Removed from the world when it goes.
class CubeColumn
{
public:
	static constexpr double kOverlap = 1e-5;  // m

	CubeColumn(btDiscreteDynamicsWorld& world, int n) : m_world(world)
	{
		add(btVector3(50, 0.5, 50), 0, btVector3(0, -0.5, 0));
		for (int i = 0; i < n; ++i) m_cubes.push_back(add(btVector3(0.5, 0.5, 0.5), 1, btVector3(0, btScalar(0.5 + i - kOverlap * (i + 1)), 0)));
	}
	~CubeColumn()
	{
		for (auto& b : m_bodies) m_world.removeRigidBody(b.get());
	}
	CubeColumn(const CubeColumn&) = delete;
	CubeColumn& operator=(const CubeColumn&) = delete;

	btRigidBody* add(const btVector3& half, double mass, const btVector3& at)
	{
		m_shapes.emplace_back(new btBoxShape(half));
		btVector3 inertia(0, 0, 0);
		if (mass > 0) m_shapes.back()->calculateLocalInertia(btScalar(mass), inertia);
		btRigidBody::btRigidBodyConstructionInfo info(btScalar(mass), nullptr, m_shapes.back().get(), inertia);
		info.m_startWorldTransform = btTransform(btQuaternion::getIdentity(), at);
		m_bodies.emplace_back(new btRigidBody(info));
		m_bodies.back()->setActivationState(DISABLE_DEACTIVATION);
		m_world.addRigidBody(m_bodies.back().get());
		return m_bodies.back().get();
	}
	const std::vector<btRigidBody*>& cubes() const { return m_cubes; }

private:
	btDiscreteDynamicsWorld& m_world;
	std::vector<std::unique_ptr<btCollisionShape>> m_shapes;
	std::vector<std::unique_ptr<btRigidBody>> m_bodies;
	std::vector<btRigidBody*> m_cubes;
};

struct Variant
{
	const char* name;
	harness::SolverKind kind;
	bool second;
	bool detect;
	int rounds;  // 0: the settings' default (or --rounds)
};

const Variant kVariants[] = {
	{"stock SI", harness::SolverKind::StockSI, false, false, 0},
	{"solver-only", harness::SolverKind::ShockSolverOnly, false, false, 0},
	{"world, second phase off", harness::SolverKind::ShockWorld, false, false, 0},
	{"world, depth refresh (old D4)", harness::SolverKind::ShockWorld, true, false, 1},
	{"world, one round (all depth)", harness::SolverKind::ShockWorld, true, true, 1},
	{"world (default)", harness::SolverKind::ShockWorld, true, true, 0},
};
const int kDefault = 5;

harness::SolverSpec specOf(const Variant& v)
{
	harness::SolverSpec s;
	s.kind = v.kind;
	s.iterations = 10;
	s.settings.m_secondCorrection = v.second;
	s.settings.m_diagnostics.m_secondDetection = v.detect;
	if (gSecondFraction > 0) s.settings.m_diagnostics.m_secondCorrectionFraction = btScalar(gSecondFraction);
	if (v.rounds > 0) s.settings.m_diagnostics.m_secondPhaseRounds = v.rounds;
	else if (gRounds > 0) s.settings.m_diagnostics.m_secondPhaseRounds = gRounds;
	return s;
}

/// Deepest narrowphase penetration of each pair of bodies touching a dynamic body (metres).
struct PairDepths : public btCollisionWorld::ContactResultCallback
{
	std::map<std::pair<const void*, const void*>, double> depth;
	btScalar addSingleResult(btManifoldPoint& cp, const btCollisionObjectWrapper* a, int, int, const btCollisionObjectWrapper* b, int, int) override
	{
		const void* p = a->getCollisionObject();
		const void* q = b->getCollisionObject();
		if (q < p) std::swap(p, q);
		double& d = depth[std::make_pair(p, q)];
		d = std::max(d, double(-cp.getDistance()));
		return 0;
	}
};

PairDepths measure(btDiscreteDynamicsWorld& world, const std::vector<btRigidBody*>& bodies)
{
	PairDepths r;
	for (btRigidBody* b : bodies) world.contactTest(b, r);
	return r;
}

void landing()
{
	std::printf("Landing: a 1 m cube falling at 6 m/s from 5 cm above a tower of three 1 m cubes (60 Hz, 10 iterations).\n");
	std::printf("Penetration by narrowphase at the end of the landing step, and the deepest in the 30 steps after it.\n");
	std::printf("%-32s %14s %14s %14s\n", "variant", "landing step", "next 0.5 s", "slop");
	for (const Variant& v : kVariants)
	{
		harness::Simulation sim(specOf(v));
		btDiscreteDynamicsWorld& world = sim.world();
		CubeColumn column(world, 3);
		std::vector<btRigidBody*> dynamic = column.cubes();
		const double top = 3 - 3 * CubeColumn::kOverlap;
		btRigidBody* falling = column.add(btVector3(0.5, 0.5, 0.5), 1, btVector3(0, btScalar(top + 0.05 + 0.5), 0));
		falling->setLinearVelocity(btVector3(0, -6, 0));
		dynamic.push_back(falling);
		double landed = -1, after = 0;
		int landingStep = -1;
		for (int i = 0; i < 60 && (landingStep < 0 || i <= landingStep + 30); ++i)
		{
			sim.step();
			const PairDepths d = measure(world, dynamic);
			const auto it = d.depth.find(falling < dynamic[2] ? std::make_pair((const void*)falling, (const void*)dynamic[2])
															  : std::make_pair((const void*)dynamic[2], (const void*)falling));
			const double depth = it == d.depth.end() ? -1 : it->second;
			if (landingStep < 0 && depth > 0)
			{
				landingStep = i;
				landed = depth;
			}
			else if (landingStep >= 0)
				for (const auto& kv : d.depth) after = std::max(after, kv.second);
		}
		const double slop = 0.18 * 9.81 / 3600.0;
		std::printf("%-32s %11.2f mm %11.2f mm %11.2f mm\n", v.name, landed * 1e3, after * 1e3, slop * 1e3);
	}
}

void ripple()
{
	std::printf("\nRipple: a 1 m cube lands at 6 m/s (from 5 cm above) on a tower of 20 1 m cubes; per step from the landing step:\n");
	std::printf("deepest narrowphase penetration in the column (mm) / largest vertical speed of a tower cube (m/s).\n");
	std::printf("%-6s", "step");
	const int kinds[] = {0, 1, kDefault};
	for (int k : kinds) std::printf(" %30s", kVariants[k].name);
	std::printf("\n");
	std::vector<std::vector<std::pair<double, double>>> trace;
	for (int k : kinds)
	{
		const Variant& v = kVariants[k];
		harness::Simulation sim(specOf(v));
		btDiscreteDynamicsWorld& world = sim.world();
		CubeColumn column(world, 20);
		const std::vector<btRigidBody*> dynamic = column.cubes();
		// Let the tower settle with the cube held away, then drop it.
		for (int i = 0; i < 60; ++i) sim.step();
		const double top = dynamic.back()->getWorldTransform().getOrigin().y() + 0.5;
		btRigidBody* falling = column.add(btVector3(0.5, 0.5, 0.5), 1, btVector3(0, btScalar(top + 0.05 + 0.5), 0));
		falling->setLinearVelocity(btVector3(0, -6, 0));
		std::vector<btRigidBody*> all = dynamic;
		all.push_back(falling);
		std::vector<std::pair<double, double>> rows;
		for (int i = 0; i < 12; ++i)
		{
			sim.step();
			const PairDepths d = measure(world, all);
			double deepest = 0, speed = 0;
			for (const auto& kv : d.depth) deepest = std::max(deepest, kv.second);
			for (btRigidBody* b : dynamic) speed = std::max(speed, double(std::fabs(b->getLinearVelocity().y())));
			rows.push_back(std::make_pair(deepest, speed));
		}
		trace.push_back(rows);
	}
	for (int i = 0; i < 12; ++i)
	{
		std::printf("%-6d", i + 1);
		for (size_t k = 0; k < trace.size(); ++k) std::printf(" %18.2f mm / %5.3f", trace[k][i].first * 1e3, trace[k][i].second);
		std::printf("\n");
	}
}

void pile(double seconds, int seeds)
{
	std::printf("\nPile: seed/dense_random, 100 cubes of 0.5 m dropped into a pit, %.0f s, seeds 1-%d (60 Hz, 10 iterations).\n", seconds, seeds);
	std::printf("Penetration by narrowphase at the end of every step: deepest over the run (mean over seeds, worst seed),\n");
	std::printf("and the mean depth of the penetrating pairs over all steps and seeds.\n");
	std::printf("%-32s %16s %16s %16s %10s\n", "variant", "deepest (mean)", "deepest (worst)", "mean of pairs", "ms/step");
	for (const Variant& v : kVariants)
	{
		double deepestSum = 0, worst = 0, depthSum = 0, ms = 0;
		long count = 0, steps = 0;
		for (int seed = 1; seed <= seeds; ++seed)
		{
			harness::Simulation sim(specOf(v));
			auto scene = scenes::createScene(sim.world(), "dense_random", {{"seed", double(seed)}});
			const std::vector<btRigidBody*> bodies = scene->dynamicBodies();
			double deepest = 0;
			const int frames = int(seconds * 60 + 0.5);
			for (int i = 0; i < frames; ++i)
			{
				btClock clock;
				sim.step();
				ms += clock.getTimeMicroseconds() * 1e-3;
				++steps;
				const PairDepths d = measure(sim.world(), bodies);
				for (const auto& kv : d.depth)
				{
					if (!(kv.second > 0)) continue;
					deepest = std::max(deepest, kv.second);
					depthSum += kv.second;
					++count;
				}
			}
			deepestSum += deepest;
			worst = std::max(worst, deepest);
			scene.reset();
		}
		std::printf("%-32s %13.1f mm %13.1f mm %13.2f mm %10.3f\n", v.name, deepestSum / seeds * 1e3, worst * 1e3, count ? depthSum / count * 1e3 : 0.0,
					ms / steps);
	}
}
}  // namespace

int main(int argc, char** argv)
{
	double seconds = 5;
	int seeds = 4;
	for (int i = 1; i < argc; ++i)
	{
		const std::string a = argv[i];
		if (a == "--pile-seconds" && i + 1 < argc)
			seconds = std::atof(argv[++i]);
		else if (a == "--rounds" && i + 1 < argc)
			gRounds = std::atoi(argv[++i]);
		else if (a == "--second-fraction" && i + 1 < argc)
			gSecondFraction = std::atof(argv[++i]);
		else if (a == "--seeds" && i + 1 < argc)
			seeds = std::atoi(argv[++i]);
		else
		{
			std::printf("usage: bsp_second_phase [--pile-seconds S] [--seeds N] [--second-fraction F] [--rounds N]\n");
			return a == "--help" ? 0 : 2;
		}
	}
	landing();
	ripple();
	pile(seconds, seeds);
	return 0;
}
