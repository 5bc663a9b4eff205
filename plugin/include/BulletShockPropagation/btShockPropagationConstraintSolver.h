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

#include "btContactGraph.h"
#include "btShockPropagationSettings.h"
#include "btShockPropagationStatistics.h"
#include "btStackLayers.h"

/// Velocity-based shock propagation (K. Erleben, ACM TOG 26(2), 2007) as a drop-in
/// btConstraintSolver. It reuses Bullet's rows (btSequentialImpulseConstraintSolver's setup and
/// projected Gauss-Seidel) and adds the contact graph, the stack layers and per-layer fixation.
///
/// One solveGroup call (dynamics phase), for the bodies, manifolds and joints Bullet hands over:
///   1. graph and layers per connected component (btContactGraph, btStackLayers);
///   2. no stacks (one layer): one ordinary solve of dt, correction first (skip the extra work);
///   3. else dynamics(f dt) on the whole group, every body free        ("global pass");
///   4. for k = 0 .. K-1 (bottom-up): fixate bodies of height k (btLayerFixation),
///      correction(layer k), dynamics((1 - f) dt, layer k), un-fixate  ("layer pass");
///   5. weight feeling only (D13): for k = K-1 .. 0 (top-down): give layer k's free bodies the
///      reactions withheld from them by the layers above, re-solve layer k  ("weight pass").
/// The second collision detection and global correction ("anti-rippling") need a world step:
/// btShockPropagationDynamicsWorld runs them (correction phase of this solver).
///
/// Decisions of algorithm.md, as built:
///  D1 fixation: infinite mass with the linear velocity kept (default), the full velocity kept,
///     or zero velocity (OpenTissue); btShockPropagationSettings::m_fixationMode. Rows are
///     re-derived, bodies untouched (btLayerFixation.h).
///  D2 f = m_weighting, default 0.5 (measured, README); f = 0 skips the global pass.
///  D3 positions are not moved between CD(t) and the end of the dynamics phase except by the
///     per-layer corrections (Bullet's push/turn write-back); positions then advance once with
///     the final velocity, by Bullet's integrateTransforms. This equals the paper's split update
///     x += f dt u1 + (1-f) dt u2 to first order and leaves free bodies exactly as stock Bullet.
///  D4 per-layer corrections use the depths of CD(t) unchanged (as OpenTissue); the second
///     correction after CD(t+dt) removes what they miss. (Updating the depths by the fixated
///     body's own correction, as TGS contact anchors do, was measured worse on the wall.) The second
///     correction is layered by default (m_layeredSecondCorrection): the paper's global form
///     squeezes mass-ratio stacks apart.
///  D5 warm starting: one impulse cache per pass. btManifoldPoint::m_appliedImpulse holds the
///     step's total normal impulse (global + layer pass; what apps read), m_prevRHS (unused by
///     Bullet's rigid-body solvers) holds the global pass's share; each pass warm-starts from its
///     own share. Lateral (friction) impulses are reported as the total of both passes; the layer
///     pass warm-starts its friction from the global pass of the same step.
///  D6 no Baumgarte in the dynamics passes (m_erp2 = 0 for contacts); Bullet's split-impulse
///     pass is replaced by correction(): normal rows, rhs = penetration depth, positions only,
///     full rotation (turn erp 1). Joint rows keep Bullet's m_erp.
///  D7 iterations per pass: m_globalIterations, m_layerIterations, m_correctionIterations.
///  D8 a manifold is a graph edge if a point is within m_graphContactThreshold; enabled joints are
///     edges and are solved in the layer of their edge. No hysteresis.
///  D9 components without a static or kinematic body are solved as one un-fixated layer.
///  D10 restitution: Bullet's (restitution curve and m_restitutionVelocityThreshold) in every
///     dynamics pass, against the fixated body's velocity.
///  D11 beyond the paper: the second correction also removes the approach velocity (inelastic,
///     normal only) at contacts that penetrate after the step and approach faster than
///     m_correctionApproachSpeed, i.e. contacts the dynamics phase missed; corrections leave
///     m_correctionSlop of penetration. Both keep a corrected contact visible to the next step.
///  D12 beyond the paper: layers are ordered by support as well as BFS distance (btStackLayers,
///     m_supportOrdering), so a body is never fixated under a free body that rests on it.
///  D13 beyond the paper: weight feeling (m_weightFeeling, setWeightFeeling; off by default). A
///     fixated body does not feel the impulses of the rows that hold the layer above it, so with
///     f = 0 the ground carries one box of a tower and a load does not tip a plank. The layer pass
///     records, per fixated body, the impulse it withheld (sum of J_F^T lambda over the layer's rows
///     with the body as fixated end F). The weight pass then runs top-down (after Xiong et al.,
///     "Two-Pass Shock Propagation", SCA 2025): the free bodies of layer k receive what the layers
///     above withheld from them (applied to their velocities), and layer k is re-solved with its
///     lower bodies still fixated, for m_weightIterations (40) sweeps; its extra impulses are
///     withheld from the bodies below in turn. The re-solve continues from the layer pass's
///     impulses (not applied twice), without gravity (already applied) and without correction. Its
///     contacts to the layer below start from the previous step's share of the load, scaled so the
///     start adds no more than the load handed down (warmStartWeightPass). Guard: a re-solve after
///     which a body rises faster than before its load arrived (it did not converge) is rejected; the
///     layer keeps its layer-pass result and hands nothing further down (statistics count it).
///     Layers whose free bodies received nothing are skipped (the top layer always); the layer
///     data of the step are reused. Cost: one more pass over every loaded layer, at 40 sweeps.
///
///  D14 beyond the paper: a fixated end that moves into the free end of a contact pushes it at most
///     at the common velocity of an inelastic collision of the two (btInelasticApproach), in the
///     layer and weight passes and in D11's approach stop; m_inelasticFixation. Joints: each
///     pass scales Bullet's joint erp by its share of the step, so joint rows ask for
///     erp * error / dt as in a stock step (positions advance once, D3).
///
/// Bad input: a body whose transform or velocity is NaN or Inf is left out of every pass (it
/// neither moves others nor is moved) with a one-time warning on stderr; manifolds touching it or
/// holding a non-finite point are left out too. Counted in getStatistics().
ATTRIBUTE_ALIGNED16(class)
btShockPropagationConstraintSolver : public btSequentialImpulseConstraintSolver
{
public:
	BT_DECLARE_ALIGNED_ALLOCATOR();

	/// What solveGroup does; set by btShockPropagationDynamicsWorld, users need not touch it.
	enum btPhase
	{
		BT_PHASE_DYNAMICS = 0,  ///< global pass + layered pass (solver-only drop-in does just this)
		BT_PHASE_CORRECTION = 1 ///< global position correction after CD(t + dt)
	};

	btShockPropagationConstraintSolver();
	explicit btShockPropagationConstraintSolver(const btShockPropagationSettings& settings);
	virtual ~btShockPropagationConstraintSolver();

	/// The paper's weighting value f in [0, 1]; values outside are clamped, NaN is ignored.
	void setWeighting(btScalar f);
	btScalar getWeighting() const { return m_settings.m_weighting; }

	/// Weight feeling (D13): pass the reactions withheld by fixation back down the stack.
	void setWeightFeeling(bool enabled) { m_settings.m_weightFeeling = enabled; }
	bool getWeightFeeling() const { return m_settings.m_weightFeeling; }

	/// All settings at once (validated like setWeighting; negative iteration counts become 0).
	void setSettings(const btShockPropagationSettings& settings);
	const btShockPropagationSettings& getSettings() const { return m_settings; }

	/// What the last step did (reset at the first solve of each step).
	const btShockPropagationStatistics& getStatistics() const { return m_stats; }

	/// Stack heights of the last step's dynamics phase, read-only, for viewers and debugging (they
	/// change nothing in the solve). Entry i is body getLayeredBody(i) at height
	/// getLayeredBodyHeight(i), as btStackLayers::getHeight gives it: 1 = resting on a static or
	/// kinematic body, 2 above that, ...; BT_STACK_HEIGHT_UNREACHED in a component with neither.
	/// Every healthy dynamic body of every solveGroup call is listed once per step, including
	/// groups solved in one pass (no stacks); static, kinematic, sleeping and skipped (NaN/Inf)
	/// bodies are not. Cleared with the statistics at the start of each step.
	int getNumLayeredBodies() const { return m_layeredBodies.size(); }
	const btCollisionObject* getLayeredBody(int i) const { return m_layeredBodies[i]; }
	int getLayeredBodyHeight(int i) const { return m_layeredBodyHeights[i]; }

	void setPhase(btPhase phase) { m_phase = phase; }
	btPhase getPhase() const { return m_phase; }
	/// Start a new step's statistics (the world calls this; solver-only use resets in prepareSolve).
	void resetStatistics()
	{
		m_stats = btShockPropagationStatistics();
		m_layeredBodies.resize(0);
		m_layeredBodyHeights.resize(0);
	}
	btShockPropagationStatistics& getStatisticsForWriting() { return m_stats; }

	virtual void prepareSolve(int numBodies, int numManifolds) BT_OVERRIDE;

	virtual btScalar solveGroup(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds, int numManifolds,
								btTypedConstraint** constraints, int numConstraints, const btContactSolverInfo& info,
								btIDebugDraw* debugDrawer, btDispatcher* dispatcher) BT_OVERRIDE;

protected:
	/// Which solve is running (decides warm-start bookkeeping and whether correction runs).
	enum btPass
	{
		BT_PASS_SINGLE,     ///< no stacks: one solve of dt with correction
		BT_PASS_GLOBAL,     ///< dynamics(f dt), every body free
		BT_PASS_LAYER,      ///< correction + dynamics((1 - f) dt) of one layer
		BT_PASS_WEIGHT,     ///< weight feeling: re-solve of one layer with the reactions from above (D13)
		BT_PASS_CORRECTION  ///< second correction (whole group, or one layer of it)
	};

	/// correction(): replaces Bullet's split-impulse iterations (positions only, normal rows).
	virtual void solveGroupCacheFriendlySplitImpulseIterations(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds,
															   int numManifolds, btTypedConstraint** constraints, int numConstraints,
															   const btContactSolverInfo& info, btIDebugDraw* debugDrawer) BT_OVERRIDE;

	/// Counts the weight pass's sweeps (statistics), then Bullet's sweep.
	virtual btScalar solveSingleIteration(int iteration, btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds,
										  int numManifolds, btTypedConstraint** constraints, int numConstraints,
										  const btContactSolverInfo& info, btIDebugDraw* debugDrawer) BT_OVERRIDE;

	/// Writes the pass's contact impulses into the per-pass caches, then Bullet's write-back.
	virtual btScalar solveGroupCacheFriendlyFinish(btCollisionObject** bodies, int numBodies, const btContactSolverInfo& info) BT_OVERRIDE;

	/// One Bullet solve (setup, fixation for layers, iterations, finish) of the given subset.
	void solvePass(btPass pass, btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds, int numManifolds,
				   btTypedConstraint** constraints, int numConstraints, const btContactSolverInfo& info, btScalar timeStep,
				   btIDebugDraw* debugDrawer);

private:
	void filterInput(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds, int numManifolds,
					 btTypedConstraint** constraints, int numConstraints);
	/// Which body of the manifold rests on the other (btContactSupport), for the layer order.
	int supportOf(const btPersistentManifold* manifold) const;
	/// D11: after a correction, no velocity into a contact that penetrates (see the .cpp).
	void stopApproachAtPenetratingContacts();
	/// J u of a contact row in the correction pass, fixated ends moving as D1 and D14 let them.
	btScalar approachVelocity(const btSolverConstraint& c, const btSolverBody& a, const btSolverBody& b) const;
	void buildGraph();
	void solveDynamics(const btContactSolverInfo& info, btIDebugDraw* debugDrawer);
	void solveCorrection(const btContactSolverInfo& info, btIDebugDraw* debugDrawer);
	void writeCorrectedTransforms(btScalar timeStep);
	/// Fill m_layerBodies / m_layerManifolds / m_layerConstraints with layer k (marking its manifolds).
	void collectLayer(int layer, btAlignedObjectArray<char>* manifoldInLayer);
	void fixateLowerBodies(int numFreeBodies, const btContactSolverInfo& info);
	/// D13: weight pass setup (continue from the layer pass's impulses, no gravity) and bookkeeping.
	void prepareWeightPass(int numFreeBodies, const btContactSolverInfo& info);
	void mapFixatedSolverBodies(int layer);
	void withholdReactions();
	bool applyWithheldReactions(int layer);
	void solveWeightPass(const btContactSolverInfo& info, btScalar layerStep, btIDebugDraw* debugDrawer);
	void prepareWarmStart(btPass pass, btPersistentManifold** manifolds, int numManifolds, btScalar timeStep);
	void prepareWeightFeelingWarmStart(btPass pass, btManifoldPoint& cp, btScalar lightWeightImpulse);
	void warmStartWeightPass(int numFreeBodies);
	void recordTotalsBefore();
	bool weightPassAccepted(int numFreeBodies);
	btScalar totalBefore(const btManifoldPoint* cp) const;
	btContactSolverInfo makePassInfo(btPass pass, const btContactSolverInfo& info, btScalar timeStep) const;

	btShockPropagationSettings m_settings;
	btShockPropagationStatistics m_stats;
	btPhase m_phase = BT_PHASE_DYNAMICS;
	btPass m_pass = BT_PASS_SINGLE;
	bool m_globalPassRan = false;
	bool m_warnedNonFinite = false;

	// Per-call working sets (kept to reuse their memory across steps).
	btAlignedObjectArray<btCollisionObject*> m_bodies;     // graph nodes: healthy dynamic bodies
	btAlignedObjectArray<btPersistentManifold*> m_manifolds;
	btAlignedObjectArray<btTypedConstraint*> m_constraints;
	btAlignedObjectArray<char> m_manifoldInLayer;
	btContactGraph m_graph;
	btStackLayers m_layers;
	btAlignedObjectArray<btCollisionObject*> m_layerBodies;
	btAlignedObjectArray<btPersistentManifold*> m_layerManifolds;
	btAlignedObjectArray<btTypedConstraint*> m_layerConstraints;
	btAlignedObjectArray<const btRigidBody*> m_fixatedRigidBody;  // per solver body of this pass: the body it was before fixation, 0 if free
	btAlignedObjectArray<btRigidBody*> m_fixatedBodies;

	// Weight feeling (D13): per graph node, the impulse (linear, angular; world frame) that the
	// layers above withheld from it; per solver body of the current pass, its node if fixated.
	bool m_weightFeelingActive = false;
	int m_currentLayer = 0;
	btScalar m_layerTimeStep = btScalar(0);
	struct btBodyVelocity
	{
		btVector3 m_linear;
		btVector3 m_angular;
	};
	btAlignedObjectArray<btBodyVelocity> m_layerVelocityBefore;  // per free body of the layer, before the load arrived
	btAlignedObjectArray<btVector3> m_withheldLinear;
	btAlignedObjectArray<btVector3> m_withheldAngular;
	btAlignedObjectArray<char> m_hasWithheld;
	btAlignedObjectArray<btVector3> m_receivedLinear;   // per node: withheld impulse handed over in this weight pass
	btAlignedObjectArray<btVector3> m_layerSupport;     // per free solver body: warm-start impulse added to it
	btAlignedObjectArray<btScalar> m_weightWarmStart;   // per contact row of the weight pass
	struct btManifoldAddress
	{
		const btManifoldPoint* m_points;  // the manifold's point cache
		int m_index;                      // index into m_manifolds
	};
	btAlignedObjectArray<btManifoldAddress> m_manifoldByAddress;  // sorted by m_points
	btAlignedObjectArray<btScalar> m_totalBefore;  // per manifold and point: T at the start of the step
	btAlignedObjectArray<int> m_nodeOfSolverBody;

	// Per step, read-only record for getLayeredBody (capacity kept across steps).
	btAlignedObjectArray<const btCollisionObject*> m_layeredBodies;
	btAlignedObjectArray<int> m_layeredBodyHeights;
};

#endif  // BT_SHOCK_PROPAGATION_CONSTRAINT_SOLVER_H
