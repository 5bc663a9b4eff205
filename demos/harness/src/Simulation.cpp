#include "harness/Simulation.h"

#include "harness/CommandLine.h"
#include "harness/ContactRecorder.h"

#include <BulletDynamics/ConstraintSolver/btNNCGConstraintSolver.h>
#include <BulletDynamics/MLCPSolvers/btDantzigSolver.h>
#include <BulletDynamics/MLCPSolvers/btMLCPSolver.h>
#include <BulletShockPropagation/btShockPropagationCommon.h>

#include <chrono>
#include <sstream>

namespace harness
{
namespace
{
struct KindName
{
	const char* name;
	SolverKind kind;
	bool weightFeeling;
	const char* description;
};
const KindName kKinds[] = {
	{"si", SolverKind::StockSI, false, "stock btSequentialImpulseConstraintSolver"},
	{"si2f", SolverKind::StockSI2Friction, false, "stock SI with two friction directions"},
	{"nncg", SolverKind::NNCG, false, "stock btNNCGConstraintSolver"},
	{"mlcp", SolverKind::MLCPDantzig, false, "stock btMLCPSolver with btDantzigSolver (cfm 1e-4)"},
	{"sp", SolverKind::ShockWorld, true, "shock propagation, btShockPropagationDynamicsWorld (defaults: weight feeling, D16)"},
	{"sp-solver", SolverKind::ShockSolverOnly, true, "shock propagation solver in a stock world (defaults)"},
	{"sp-classic", SolverKind::ShockWorld, false, "Erleben's classic method: no weight feeling (lower bodies never feel the upper ones)"},
	{"sp-solver-classic", SolverKind::ShockSolverOnly, false, "the classic method's solver in a stock world"},
};

/// A world that adds the wall-clock time of each collision detection to *sink (milliseconds).
template <class World>
class CollisionTimedWorld : public World
{
public:
	CollisionTimedWorld(double* sink, btDispatcher* dispatcher, btBroadphaseInterface* broadphase, btConstraintSolver* solver,
						btCollisionConfiguration* configuration)
		: World(dispatcher, broadphase, solver, configuration), m_sink(sink)
	{
	}
	void performDiscreteCollisionDetection() override
	{
		const auto start = std::chrono::steady_clock::now();
		World::performDiscreteCollisionDetection();
		*m_sink += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
	}

private:
	double* m_sink;
};

/// A solver of type Base wrapped with the recorder's hooks; *recorder points at its recorder.
template <class Base, class... Args>
Base* recording(ContactRecorder** recorder, Args&&... args)
{
	RecordingSolver<Base>* solver = new RecordingSolver<Base>(std::forward<Args>(args)...);
	*recorder = &solver->recorder();
	return solver;
}
}  // namespace

std::string solverKindNames()
{
	std::ostringstream out;
	for (const KindName& k : kKinds) out << (&k == kKinds ? "" : ", ") << k.name;
	out << " (append -subN for N sub-steps, e.g. si-sub4)";
	return out.str();
}

bool parseSolverKind(const std::string& text, SolverSpec& spec, std::string& error)
{
	std::string base = text;
	int substeps = 1;
	const std::string::size_type sub = text.find("-sub");
	if (sub != std::string::npos)
	{
		base = text.substr(0, sub);
		const std::string count = text.substr(sub + 4);
		char* end = nullptr;
		const long n = std::strtol(count.c_str(), &end, 10);
		if (count.empty() || *end != '\0' || n < 1 || n > 1000)
		{
			error = "bad sub-step count in '" + text + "' (want -subN with N in 1..1000)";
			return false;
		}
		substeps = int(n);
	}
	for (const KindName& k : kKinds)
	{
		if (base == k.name)
		{
			spec.kind = k.kind;
			spec.settings.m_weightFeeling = k.weightFeeling;
			spec.substeps = substeps;
			return true;
		}
	}
	error = "unknown solver '" + text + "'; valid: " + solverKindNames();
	return false;
}

std::string SolverSpec::name() const
{
	std::ostringstream out;
	for (const KindName& k : kKinds)
		if (k.kind == kind && k.weightFeeling == settings.m_weightFeeling) out << k.name;
	if (substeps > 1) out << "-sub" << substeps;
	return out.str();
}

std::string SolverSpec::label() const
{
	std::ostringstream out;
	out << name() << " it=" << iterations;
	if (isPlugin()) out << pluginSettingsLabel(settings);
	return out.str();
}

Simulation::Simulation(const SolverSpec& spec, double timeStep, double gravity)
	: m_spec(spec), m_timeStep(timeStep), m_gravity(gravity)
{
	m_configuration.reset(new btDefaultCollisionConfiguration());
	m_dispatcher.reset(new btCollisionDispatcher(m_configuration.get()));
	m_broadphase.reset(new btDbvtBroadphase());

	if (spec.isPlugin())
	{
		// Sweep counts follow the world's m_numIterations (set below), as in an app.
		m_shockSolver = recording<btShockPropagationConstraintSolver>(&m_recorder, spec.settings);
		m_solver.reset(m_shockSolver);
	}
	else if (spec.kind == SolverKind::NNCG)
	{
		m_solver.reset(recording<btNNCGConstraintSolver>(&m_recorder));
	}
	else if (spec.kind == SolverKind::MLCPDantzig)
	{
		m_mlcpInterface.reset(new btDantzigSolver());
		m_solver.reset(recording<btMLCPSolver>(&m_recorder, m_mlcpInterface.get()));
	}
	else
	{
		m_solver.reset(recording<btSequentialImpulseConstraintSolver>(&m_recorder));
	}

	if (spec.kind == SolverKind::ShockWorld)
		m_world.reset(new CollisionTimedWorld<btShockPropagationDynamicsWorld>(&m_collisionMs, m_dispatcher.get(), m_broadphase.get(), m_solver.get(), m_configuration.get()));
	else
		m_world.reset(new CollisionTimedWorld<btDiscreteDynamicsWorld>(&m_collisionMs, m_dispatcher.get(), m_broadphase.get(), m_solver.get(), m_configuration.get()));

	m_world->setGravity(btVector3(0, btScalar(-gravity), 0));
	btContactSolverInfo& info = m_world->getSolverInfo();
	info.m_numIterations = spec.iterations;
	if (spec.kind == SolverKind::StockSI2Friction) info.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
	if (spec.kind == SolverKind::MLCPDantzig) info.m_globalCfm = btScalar(1e-4);
}

Simulation::~Simulation()
{
	// Scenes own their bodies and remove them from the world before it goes.
	m_world.reset();
	m_solver.reset();
}

void Simulation::step()
{
	const btScalar frame = btScalar(m_timeStep);
	m_collisionMs = 0;
	m_world->stepSimulation(frame, m_spec.substeps, frame / btScalar(m_spec.substeps));
	++m_steps;
}
}  // namespace harness
