// Read-only capture of one step's contact problem and of the impulses a solver applied, for the
// accuracy reference (harness/ContactProblem.h). Every solver of harness::Simulation is wrapped in
// RecordingSolver<Base>; while the recorder is disarmed the wrapper only forwards calls.
//
// When armed for a step:
//  - at the start of each dynamics solveGroup call, the rows are built by a separate stock
//    btSequentialImpulseConstraintSolver setup (two friction directions, no warm start) from the
//    same bodies and manifolds: the problem every solver is measured on, whatever rows it builds
//    itself. Nothing of the world changes (companion ids are reset, the manifold points' friction
//    directions restored).
//  - after each solve pass (before Bullet's write-back), the pass's rows are read: the normal
//    impulse and the friction impulse as a world vector, summed per manifold point over the step.
//    The plugin runs a global and a layer pass; both count ("its impulses" = the total applied over
//    the step). Its position corrections carry no velocity impulse and are not counted, nor are the
//    approach-stopping impulses of its second correction (D11; resting scenes have none).
//  - the recorded impulses are mapped onto the reference rows: normal rows take the summed normal
//    impulse, friction rows the summed friction vector projected on their direction.
// Sub-steps: only the first internal step of a frame is captured. Joint rows are not captured.
#pragma once

#include <harness/ContactProblem.h>

#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>

#include <memory>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

class btShockPropagationConstraintSolver;

namespace harness
{
class ContactRecorder
{
public:
	ContactRecorder();
	~ContactRecorder();

	/// Capture the next step (call before Simulation::step()).
	void arm();
	/// True while the armed step's first internal step is being captured.
	bool armed() const { return m_state == State::Capturing; }
	/// The captured problem of the last step (empty if none was captured); disarms.
	ContactProblem take();

	// Called by RecordingSolver.
	/// A dynamics solve of a new internal step begins.
	void beginStep();
	void captureGroup(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds, int numManifolds,
					  const btContactSolverInfo& info);
	void recordPass(const btConstraintArray& contactRows, const btConstraintArray& frictionRows, bool twoFrictionRows);
	void finishGroup();

private:
	class RowBuilder;
	struct Applied
	{
		double normal = 0;
		btVector3 tangent = btVector3(0, 0, 0);
	};
	enum class State
	{
		Idle,       ///< not armed
		Waiting,    ///< armed, the step has not started
		Capturing,  ///< inside the first internal step
		Done        ///< captured; later internal steps of the frame are ignored
	};
	void clear();
	std::unique_ptr<RowBuilder> m_builder;
	State m_state = State::Idle;
	ContactProblem m_problem;
	std::unordered_map<const btCollisionObject*, int> m_bodyIndex;
	std::unordered_map<const btManifoldPoint*, Applied> m_applied;
	std::vector<const btManifoldPoint*> m_rowPoint;  // per row of m_problem, its manifold point
	std::vector<btVector3> m_rowDirection;           // per row, its world direction (for body A)
	size_t m_firstRowOfGroup = 0;
};

/// Any Bullet solver derived from btSequentialImpulseConstraintSolver, with the recorder's hooks.
template <class Base>
class RecordingSolver : public Base
{
	static_assert(std::is_base_of<btSequentialImpulseConstraintSolver, Base>::value, "needs Bullet's SI rows");

public:
	template <class... Args>
	explicit RecordingSolver(Args&&... args) : Base(std::forward<Args>(args)...)
	{
	}

	ContactRecorder& recorder() { return m_recorder; }

	void prepareSolve(int numBodies, int numManifolds) override
	{
		Base::prepareSolve(numBodies, numManifolds);
		m_recorder.beginStep();
	}

	btScalar solveGroup(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds, int numManifolds,
						btTypedConstraint** constraints, int numConstraints, const btContactSolverInfo& info, btIDebugDraw* debugDrawer,
						btDispatcher* dispatcher) override
	{
		const bool record = m_recorder.armed();
		if (record) m_recorder.captureGroup(bodies, numBodies, manifolds, numManifolds, info);
		const btScalar result = Base::solveGroup(bodies, numBodies, manifolds, numManifolds, constraints, numConstraints, info, debugDrawer, dispatcher);
		if (record) m_recorder.finishGroup();
		return result;
	}

protected:
	btScalar solveGroupCacheFriendlyFinish(btCollisionObject** bodies, int numBodies, const btContactSolverInfo& info) override
	{
		if (m_recorder.armed())
			m_recorder.recordPass(this->m_tmpSolverContactConstraintPool, this->m_tmpSolverContactFrictionConstraintPool,
								  (info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) != 0);
		return Base::solveGroupCacheFriendlyFinish(bodies, numBodies, info);
	}

private:
	ContactRecorder m_recorder;
};
}  // namespace harness
