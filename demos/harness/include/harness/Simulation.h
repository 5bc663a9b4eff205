// Shared by the demo program, the tests and the benchmarks: a Bullet world with one of the
// compared solvers, stepped at a fixed rate. Not part of the shipped plugin.
#pragma once

#include <BulletShockPropagation/btShockPropagationSettings.h>
#include <btBulletDynamicsCommon.h>

#include <memory>
#include <string>
#include <vector>

class btShockPropagationConstraintSolver;
class btMLCPSolverInterface;

namespace harness
{
class ContactRecorder;

enum class SolverKind
{
	StockSI,          ///< btSequentialImpulseConstraintSolver, Bullet defaults
	StockSI2Friction, ///< the same with SOLVER_USE_2_FRICTION_DIRECTIONS
	NNCG,             ///< btNNCGConstraintSolver
	MLCPDantzig,      ///< btMLCPSolver + btDantzigSolver, m_globalCfm = 1e-4 (docs/bullet-facts.md)
	ShockWorld,       ///< btShockPropagationDynamicsWorld (full algorithm)
	ShockSolverOnly   ///< btShockPropagationConstraintSolver in a stock btDiscreteDynamicsWorld
};

struct SolverSpec
{
	SolverKind kind = SolverKind::StockSI;
	int iterations = 10;  ///< PGS sweeps: the world's m_numIterations (the plugin's sweep counts follow it)
	int substeps = 1;     ///< sub-steps per frame (stepSimulation with dt / substeps)
	/// The plugin's settings, as an app would pass them (plugin kinds only; the stock kinds ignore
	/// them). Programs vary them through the plugin flags of harness/CommandLine.h.
	btShockPropagationSettings settings;
	/// ShockWorld or ShockSolverOnly: the one place "is this the plugin" is spelled out.
	bool isPlugin() const { return kind == SolverKind::ShockWorld || kind == SolverKind::ShockSolverOnly; }
	std::string name() const;   ///< the solver name as parsed, e.g. "si-sub4", "sp", "sp-classic"
	std::string label() const;  ///< name() with iterations and, for the plugin, f and every non-default plugin flag
};

/// Names: si, si2f, nncg, mlcp, sp, sp-solver, sp-classic, sp-solver-classic; a "-subN" suffix sets sub-steps (si-sub4).
/// Returns false with a message listing the valid names.
bool parseSolverKind(const std::string& text, SolverSpec& spec, std::string& error);
std::string solverKindNames();

class Simulation
{
public:
	explicit Simulation(const SolverSpec& spec, double timeStep = 1.0 / 60.0, double gravity = 9.81);
	~Simulation();
	Simulation(const Simulation&) = delete;
	Simulation& operator=(const Simulation&) = delete;

	btDiscreteDynamicsWorld& world() { return *m_world; }
	const SolverSpec& spec() const { return m_spec; }
	double timeStep() const { return m_timeStep; }
	double gravity() const { return m_gravity; }
	double time() const { return m_steps * m_timeStep; }
	int steps() const { return m_steps; }
	/// The plugin's solver (nullptr for stock solvers).
	btShockPropagationConstraintSolver* shockSolver() { return m_shockSolver; }
	/// Captures a step's contact problem and the solver's impulses (harness/ContactRecorder.h).
	ContactRecorder& recorder() { return *m_recorder; }
	/// Wall-clock time of Bullet's collision detection (performDiscreteCollisionDetection, every
	/// call: the plugin world makes two) in the last step() (ms).
	double collisionMs() const { return m_collisionMs; }

	/// Advance one frame of timeStep (split into spec().substeps sub-steps).
	void step();

private:
	SolverSpec m_spec;
	double m_timeStep;
	double m_gravity;
	int m_steps = 0;
	std::unique_ptr<btDefaultCollisionConfiguration> m_configuration;
	std::unique_ptr<btCollisionDispatcher> m_dispatcher;
	std::unique_ptr<btBroadphaseInterface> m_broadphase;
	std::unique_ptr<btConstraintSolver> m_solver;
	std::unique_ptr<btMLCPSolverInterface> m_mlcpInterface;
	std::unique_ptr<btDiscreteDynamicsWorld> m_world;
	btShockPropagationConstraintSolver* m_shockSolver = nullptr;
	ContactRecorder* m_recorder = nullptr;
	double m_collisionMs = 0;
};
}  // namespace harness
