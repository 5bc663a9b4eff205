/*
BulletShockPropagation - velocity-based shock propagation for Bullet
Copyright (c) 2026 the BulletShockPropagation authors

This software is provided 'as-is', without any express or implied warranty.
In no event will the authors be held liable for any damages arising from the use of this software.
Permission is granted to anyone to use this software for any purpose,
including commercial applications, and to alter it and redistribute it freely,
subject to the following restrictions:
1. The origin of this software must not be misrepresented; you must not claim that you wrote the original software. If you use this software in a product, an acknowledgment in the product documentation would be appreciated but is not required.
2. Altered source versions must be plainly marked as such, and must not be misrepresented as being the original software.
3. This notice may not be removed or altered from any source distribution.
*/

#ifndef BT_SHOCK_PROPAGATION_CONSTRAINT_SOLVER_H
#define BT_SHOCK_PROPAGATION_CONSTRAINT_SOLVER_H

#include "BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h"
#include "LinearMath/btThreads.h"  // BT_OVERRIDE
#include "btShockPropagationExport.h"

#include "btContactGraph.h"
#include "btShockPropagationSettings.h"
#include "btShockPropagationStatistics.h"
#include "btStackLayers.h"

class btPositionCorrection;
class btShockPredictor;
class btShockPropagationDynamicsWorld;

/// Velocity-based shock propagation (K. Erleben, ACM TOG 26(2), 2007) as a drop-in
/// btConstraintSolver. It reuses Bullet's rows (btSequentialImpulseConstraintSolver's setup, row
/// kernels and finish) and adds the contact graph, the stack layers and per-layer fixation.
///
/// One solveGroup call, for the bodies, manifolds and joints Bullet hands over (docs/design.md,
/// section 2):
///   1. contact graph and stack layers (btContactGraph, btStackLayers);
///   2. components without stacks (one layer): Bullet's own solveGroup, with the app's settings;
///   3. components with stacks: the converging step, its stages called in order:
///        setupRows          Bullet's rows, set up once for the step's dt as a stock step sets them
///                           up (restitution, joint rows, motors), two friction rows per point,
///                           every row from zero impulse, each contact row given its layer;
///        predictVelocities  shock propagation: up-and-down cycles of a pass up the layers with
///                           each layer's lower bodies fixated (infinite mass, D1) and a weight-
///                           feeling pass down, every withheld reaction delivered to both bodies,
///                           each cycle line searched on kinetic energy;
///        correctVelocities  Bullet's own sweeps over every row, every body free, from the
///                           predictor's impulses, ceil(f N) at most, ended once converged;
///        finishRows         Bullet's finish (applied impulses, joint feedback and breaking);
///        correctPositions   the positions corrected layer by layer at the depths of CD(t)
///                           (btPositionCorrection).
///      N is the app's btContactSolverInfo::m_numIterations unless the settings fix the counts.
///      Every impulse acts on both bodies of its row, so momentum and angular momentum change only
///      through static and kinematic bodies and external forces.
/// btShockPropagationDynamicsWorld adds the second phase after the positions advance.
///
/// Bad input: a body whose transform or velocity is NaN or Inf is left out of every pass (it
/// neither moves others nor is moved) with a one-time warning on stderr; manifolds touching it or
/// holding a non-finite point are left out too. Counted in getStatistics().
ATTRIBUTE_ALIGNED16(class)
BT_SHOCK_PROPAGATION_API btShockPropagationConstraintSolver : public btSequentialImpulseConstraintSolver
{
public:
	BT_DECLARE_ALIGNED_ALLOCATOR();

	btShockPropagationConstraintSolver();
	explicit btShockPropagationConstraintSolver(const btShockPropagationSettings& settings);
	virtual ~btShockPropagationConstraintSolver();

	/// The weighting value f in [0, 1]; values outside are clamped, NaN is ignored.
	void setWeighting(btScalar f);
	btScalar getWeighting() const { return m_settings.m_weighting; }

	/// Weight feeling (D13): pass the reactions withheld by fixation back down the stack.
	void setWeightFeeling(bool enabled) { m_settings.m_weightFeeling = enabled; }
	bool getWeightFeeling() const { return m_settings.m_weightFeeling; }

	/// All settings at once (validated like setWeighting; iteration counts below
	/// BT_SHOCK_ITERATIONS_FROM_WORLD become BT_SHOCK_ITERATIONS_FROM_WORLD).
	void setSettings(const btShockPropagationSettings& settings);
	const btShockPropagationSettings& getSettings() const { return m_settings; }

	/// What the last step did (reset when a step's solve starts).
	const btShockPropagationStatistics& getStatistics() const { return m_stats; }

	/// Stack heights of the last step, read-only, for viewers and debugging (they change nothing
	/// in the solve). Entry i is body getLayeredBody(i) at height getLayeredBodyHeight(i), as
	/// btStackLayers::getHeight gives it: 1 = resting on a static or kinematic body, 2 above
	/// that, ...; BT_STACK_HEIGHT_UNREACHED in a component with neither. Every healthy dynamic
	/// body of every solveGroup call is listed once per step, including groups solved by Bullet's
	/// own solver (no stacks); static, kinematic, sleeping and skipped (NaN/Inf) bodies are not.
	int getNumLayeredBodies() const { return m_layeredBodies.size(); }
	const btCollisionObject* getLayeredBody(int i) const { return m_layeredBodies[i]; }
	int getLayeredBodyHeight(int i) const { return m_layeredBodyHeights[i]; }

	virtual void prepareSolve(int numBodies, int numManifolds) BT_OVERRIDE;

	/// Throws std::logic_error if the world called prepareSolve and allSolved without a solveGroup
	/// in between: btDiscreteDynamicsWorld always calls solveGroup at least once per step, while
	/// btMultiBodyDynamicsWorld keeps solving with its own btMultiBodyConstraintSolver, so the
	/// plugin would silently do nothing there (not supported; use btDiscreteDynamicsWorld or
	/// btShockPropagationDynamicsWorld).
	virtual void allSolved(const btContactSolverInfo& info, class btIDebugDraw* debugDrawer) BT_OVERRIDE;

	virtual btScalar solveGroup(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds, int numManifolds,
								btTypedConstraint** constraints, int numConstraints, const btContactSolverInfo& info,
								btIDebugDraw* debugDrawer, btDispatcher* dispatcher) BT_OVERRIDE;

private:
	friend class btShockPropagationDynamicsWorld;
	btShockPropagationConstraintSolver(const btShockPropagationConstraintSolver&);
	btShockPropagationConstraintSolver& operator=(const btShockPropagationConstraintSolver&);

	/// The world's second correction (after positions advanced): every active dynamic body and
	/// every manifold of the world, depths recomputed from the new transforms, fraction of each
	/// depth beyond the slop removed. Returns whether any point was deeper than the slop.
	bool correctAfterStep(btCollisionObject** objects, int numObjects, btPersistentManifold** manifolds, int numManifolds,
						  btTypedConstraint** constraints, int numConstraints, const btContactSolverInfo& info, btScalar fraction);

	void filterInput(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds, int numManifolds,
					 btTypedConstraint** constraints, int numConstraints, bool countInStatistics);
	/// An object's graph node while the companion ids hold node indices (buildGraph,
	/// correctPositions), else BT_CONTACT_GRAPH_ROOT.
	int nodeOf(const btCollisionObject* object) const;
	void buildGraph();
	// A group without stacks: Bullet's own solve, warm started from its own impulses.
	void solveFlat(const btContactSolverInfo& info, btIDebugDraw* debugDrawer);
	/// In a group with stacks, splits the components without stacks off into m_flat*, the rest
	/// into m_stacked* (a flat component that a joint or an edgeless manifold ties to a stacked
	/// one counts as stacked); false if either part is empty.
	bool splitOffFlatComponents();
	/// The tallest body height of each contact-graph component of m_bodies (m_tallestOfComponent).
	btAlignedObjectArray<int>& tallestOfComponents();
	void startFromOwnImpulses();
	void markPointsFelt();
	// The converging step of a group that holds a stack, its stages in order (docs/design.md, section 2).
	void solveConverging(const btContactSolverInfo& info, btIDebugDraw* debugDrawer);
	btContactSolverInfo setupRows(const btContactSolverInfo& info, btIDebugDraw* debugDrawer);
	void predictVelocities(const btContactSolverInfo& info);
	void correctVelocities(const btContactSolverInfo& info, const btContactSolverInfo& stepInfo);
	void finishRows(const btContactSolverInfo& stepInfo);
	void markPointsSolved();
	void assignRowsToLayers();
	btScalar largestGravity() const;  ///< m/s^2, over the group's dynamic bodies
	/// D30's and D33's reach (m): m_boxFaceReachPerFall |g| dt^2.
	btScalar faceReach(btScalar timeStep) const;
	/// D33 over the group's manifolds (m_completeContactPatches); returns the points added or traded.
	int completeContactPatches(btScalar timeStep);
	/// Position correction of the group's contacts; fresh: depths from the current transforms;
	/// fraction of each depth removed (negative: m_diagnostics.m_correctionFraction). Returns
	/// whether any point was deeper than the slop.
	bool correctPositions(const btContactSolverInfo& info, bool fresh, bool layered, btScalar fraction = btScalar(-1));
	int sweepCount(int setting, int worldIterations) const;

	btShockPropagationSettings m_settings;
	btShockPropagationStatistics m_stats;
	bool m_warnedNonFinite = false;
	int m_solveGroupCalls = 0;  // since the last prepareSolve

	// Per-call working sets (kept to reuse their memory across steps).
	btAlignedObjectArray<btCollisionObject*> m_bodies;  // graph nodes: healthy dynamic bodies
	btAlignedObjectArray<btPersistentManifold*> m_manifolds;
	btAlignedObjectArray<btTypedConstraint*> m_constraints;
	btAlignedObjectArray<int> m_edgeOfManifold;    // graph edge of each manifold, -1 if none
	btAlignedObjectArray<int> m_contactRowLayer;
	btAlignedObjectArray<int> m_solverBodyOfNode;
	btAlignedObjectArray<int> m_tallestOfComponent;  // tallest height per component (tallestOfComponents)
	btAlignedObjectArray<int> m_keptEdges;
	// A group's parts without and with stacks (splitOffFlatComponents; capacity kept across steps).
	btAlignedObjectArray<btCollisionObject*> m_flatBodies, m_stackedBodies;
	btAlignedObjectArray<btPersistentManifold*> m_flatManifolds, m_stackedManifolds;
	btAlignedObjectArray<btTypedConstraint*> m_flatConstraints, m_stackedConstraints;
	btContactGraph m_graph;
	btStackLayers m_layers;
	btPositionCorrection* m_correction;
	btShockPredictor* m_predictor;
	btAlignedObjectArray<int> m_heightOfSolverBody;  // converging step: stack height of each solver body
	btAlignedObjectArray<int> m_componentOfSolverBody;  // converging step: contact-graph component of each solver body

	// Per step, read-only record for getLayeredBody (capacity kept across steps).
	btAlignedObjectArray<const btCollisionObject*> m_layeredBodies;
	btAlignedObjectArray<int> m_layeredBodyHeights;
};

#endif  // BT_SHOCK_PROPAGATION_CONSTRAINT_SOLVER_H
