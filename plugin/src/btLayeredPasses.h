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

#ifndef BT_SHOCK_PROPAGATION_LAYERED_PASSES_H
#define BT_SHOCK_PROPAGATION_LAYERED_PASSES_H

#include "BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h"
#include "btLayerFixation.h"
#include "btCholesky6.h"
#include "btLoadTransfer.h"
#include "btSlidingComposite.h"
#include "btWithheldReactions.h"

class btPersistentManifold;

class btStackLayers;

/// The weight pass's settings for one step (D16).
struct btWeightPassParams
{
	bool m_transfer = true;           ///< load transfer before the sweeps (btLoadTransfer.h)
	btScalar m_convergedSpeed = 0;    ///< m/s: a re-solve whose last sweep changed no row's velocity by more has converged
	btScalar m_timeStep = 0;          ///< s
	btScalar m_slack = 0;             ///< a load may speed a body up by this share of its |g| dt beyond its loads' approach
	btScalar m_tipGain = 1;           ///< a converged re-solve may speed a body that tips or slides up by this share of |g| dt
	btScalar m_tipMargin = 0;         ///< share of the support's size the load must act outside of to tip it
	bool m_transferSmallLoads = true; ///< D20: loads below m_convergedSpeed are transferred, not re-solved
	bool m_finalBlocks = false;       ///< D31: a re-solve ends with its free bodies' support blocks (D19's solve)
	/// D23, m/s: a sliding base's composite holds in the weight pass while the load handed to it
	/// across its support changes its velocity by at most this (else it is re-solved alone)
	btScalar m_compositeTolerance = 0;
	/// D25: a body statics says must tip carries what rests on it as one rigid body (btTippingComposite.h)
	bool m_tippingComposites = false;
	/// D26: a rejected re-solve restores the layer's bodies of its island only (else the whole layer)
	bool m_rejectPerIsland = false;
	/// D27: an impact load (beyond m_tipGain |g| dt) tips a composite where it acts outside the
	/// support, whatever the composite's weight does
	bool m_impactTipping = false;
	/// D28: the guard judges an unconverged re-solve by the speed of the body's kinetic energy
	/// (spin included), not its centre of mass's speed alone
	bool m_guardSpin = false;
	/// D29: a body that slides under its up pass and its re-solve carries what rests on it as one
	/// rigid body (D25's composite, members that can stick only)
	bool m_rigidSliding = false;
};

/// The up pass's schedule for each layer (D7, D19).
struct btLayerSweeps
{
	int m_max = 10;                ///< most sweeps (the app's N, at least the floor: D22)
	int m_jointLayerMax = 10;      ///< most sweeps of the layer holding the joint rows (the app's N, as a stock solve)
	int m_min = -1;                ///< fewest sweeps before the convergence test ends the layer; negative: always m_max
	btScalar m_convergedSpeed = 0; ///< m/s: a sweep that changed no row's velocity by more ends the layer
	bool m_block = false;          ///< solve each free body's support rows as one block first (btSupportBlock.h)
	/// D23, m/s: a free body whose support friction is at its Coulomb limit and slips by more than
	/// this (at setup and after the global pass) carries what rests on it; 0: never
	btScalar m_compositeSlip = 0;
	/// D29: note which free bodies end their layer with a support friction row at its Coulomb bound
	bool m_markSliding = false;
};

/// The rows and bodies of one step, as Bullet's setup left them in the solver's pools.
struct btSolverPools
{
	btAlignedObjectArray<btSolverBody>& m_bodies;
	btConstraintArray& m_contacts;
	btConstraintArray& m_frictions;
	btConstraintArray& m_rollingFrictions;
	btConstraintArray& m_joints;
	btSingleConstraintRowSolver m_generic;     ///< Bullet's row kernel with both limits
	btSingleConstraintRowSolver m_lowerLimit;  ///< Bullet's row kernel for contact normals
};

/// The layered part of the step (D15): sweep schedules over subsets of the rows Bullet set up
/// once for the whole step, with a fixation mask per layer.
///
///  - build(): every row goes to the layer of its graph edge (friction and rolling rows follow
///    their contact row); rows of no edge go to layer 0, where nothing is fixated.
///  - solveLayer(k): the layer's lower bodies are fixated (btLayerFixation: rows re-derived,
///    solver bodies' inverse mass zeroed), then Bullet's own row kernels sweep the layer's rows
///    (joints, contacts, friction, rolling friction, as a stock sweep orders them), then rows
///    and bodies are restored. Impulses accumulate on the step's single impulse per row, so
///    applied impulses, joint feedback, breaking and motor limits see one step.
///  - Per-pass impulse bookkeeping (btWithheldReactions): the change of each row's impulse in
///    a pass where one end is fixated is the reaction fixation withheld from that end; weight
///    feeling (D13) hands it down in a top-down pass (solveWeightPass).
/// Private to the plugin.
class btLayeredPasses
{
public:
	/// contactRowLayer: per contact row, its layer (-1: none, solved in layer 0). Joint rows are
	/// no graph edges (D8): all of them are swept in layer 0. solverBodyOfNode: per graph node, its
	/// solver body.
	void build(const btStackLayers& layers, const btAlignedObjectArray<int>& contactRowLayer, const btAlignedObjectArray<int>& solverBodyOfNode,
			   const btSolverPools& pools);

	int getNumLayers() const { return m_numLayers; }
	/// D18, before setup: a contact point Bullet created this step (it replaced one of the
	/// manifold's points or joined them) starts from no impulse. Where the pair's points together
	/// carried T last step and carry less now, and the pair rests (every new point's relative
	/// velocity below restSpeed, m/s), the new points share the rest, felt by both bodies.
	void restorePairLoads(btPersistentManifold** manifolds, int numManifolds, btScalar restSpeed);
	/// After the finish: each manifold's total normal impulse, for the next step.
	void recordPairLoads(btPersistentManifold** manifolds, int numManifolds);
	/// The world's step ended.
	void endStep();
	/// Sweeps of the joint rows in their layer (at least the layer's own count).
	void setJointSweeps(int sweeps) { m_jointSweeps = sweeps; }
	/// D24: each support block keeps its factor for the weight pass's load transfer of the same rows.
	void setSharedBlockFactor(bool share) { m_shareFactor = share; }
	/// D24: load transfers solved with a block's factor since the last call (and the count reset).
	int takeSharedFactorTransfers()
	{
		const int n = m_sharedFactorTransfers;
		m_sharedFactorTransfers = 0;
		return n;
	}
	/// D29: the composites of sliding bodies among the tipping composites (counted since the last
	/// call, and reset).
	int takeRigidSlidingComposites()
	{
		const int n = m_rigidSlidingComposites;
		m_rigidSlidingComposites = 0;
		return n;
	}
	/// D25: tipping composites solved since the last call (and the count reset).
	int takeTippingComposites()
	{
		const int n = m_tippingComposites;
		m_tippingComposites = 0;
		return n;
	}

	/// Layer k with its lower bodies fixated: the support blocks (D19, if asked), then sweeps.
	/// withhold: record the reactions fixation keeps from the lower bodies, for solveWeightPass.
	/// Returns the sweeps run.
	int solveLayer(int layer, const btLayerSweeps& sweeps, const btLayerFixationParams& params, bool withhold, const btSolverPools& pools);

	/// After setup, before any pass: Bullet's warm start applied each contact row's cached total T
	/// to both ends; the lower (fixated) end felt only the share F of it last step (the global
	/// pass's share, or all of it when the weight pass handed it down). Take (1 - coupling) of the
	/// rest back from the lower end and hold it back: coupling 0 restarts from the state last step
	/// ended in, 1 is Bullet's coupled warm start (D5).
	void withholdUnfeltWarmStart(const btSolverPools& pools, btScalar warmstartingFactor, btScalar coupling);
	/// After the passes: store each contact point's felt share F for the next step's warm start
	/// (delivered: the weight pass handed every held-back impulse down, so F = T).
	void storeFeltShares(const btSolverPools& pools, bool delivered);

	/// D13/D16, top-down: the free bodies of each layer receive what the layers above withheld from
	/// them; their support rows take that load (load transfer), then the layer is re-solved with
	/// its own lower bodies fixated (withholding in turn). Returns the number of sweeps run.
	/// Guard: a re-solve that left a free body faster than its load could push it could not carry
	/// the load, unless it converged and the body tips or slides as statics and friction allow
	/// (D16, D17); a rejected layer keeps its state from before and hands nothing on (counted in
	/// *rejected).
	int solveWeightPass(int sweeps, const btLayerFixationParams& params, const btSolverPools& pools, const btWeightPassParams& weight, int* rejected);

	/// D23, after setup and the warm start, before any pass: which friction rows slip by more
	/// than `speed` (m/s) as the step begins (btRowSlipAtSetup).
	void markSlipsAtSetup(const btSolverPools& pools, btScalar speed);
	/// D25: the bodies resting on solver body `id` (free in `layer`), through contacts that push
	/// now and point up into the upper body, that rest on nothing else, appended to m_tipMembers
	/// (id first) as composite `mark` (m_tipOf). False (nothing kept) if fewer than two, or a
	/// member is jointed, has factors, or belongs to another composite.
	bool gatherTippingMembers(int layer, int id, int mark, const btSolverPools& pools);
	/// D23, after the weight pass: each composite the weight pass held moves as one across its
	/// support (btEqualizeAcross). Returns the number of composites this step.
	int finishComposites(const btSolverPools& pools);


private:
	/// D23: the layer's sliding bases (before fixation), their sub-stacks equalized; and, after the
	/// layer's sweeps, each sub-stack moved across the support as its base moved.
	void formComposites(int layer, const btSolverPools& pools, btScalar slip);
	void carryComposites(int layer, const btSolverPools& pools);
	/// D23, weight pass: the layer's composites active again, unless the load handed to the base
	/// across its support exceeds `tolerance` (m/s); and the composites' motion after the re-solve.
	void activateComposites(int layer, const btSolverPools& pools, btScalar tolerance);
	void shareCompositeMotion(int layer, const btSolverPools& pools);
	/// The velocity change across its support that the impulse the layer's rows gave a composite's
	/// base since the layer's fixation (m_impulseBefore) gives the whole composite (m/s).
	btVector3 compositeShift(int layer, const btSlidingComposite& comp, const btSolverPools& pools);
	void deactivateComposites(bool moveMembers, const btSolverPools& pools);
	int compositeOf(int solverBody) const { return solverBody < m_compositeOf.size() ? m_compositeOf[solverBody] : -1; }
	/// The active composite whose base is this end of a row, if the row is one its mass changes
	/// (friction; fixate() re-derives and release() restores exactly these); else -1.
	int compositeRowEnd(int solverBody, btSolverRowKind kind) const { return kind == BT_ROW_FRICTION ? compositeOf(solverBody) : -1; }
	int freeIndexOf(int layer, int node) const;
	void fixate(int layer, const btLayerFixationParams& params, const btSolverPools& pools);
	void release(int layer, bool withhold, const btSolverPools& pools);
	/// Zero (and keep) the inverse mass of the layer's lower bodies' solver bodies; and restore it.
	void zeroFixatedMasses(int layer, const btSolverPools& pools);
	void restoreFixatedMasses(int layer, const btSolverPools& pools);
	/// A row's impulse change in a pass where its end fixA (or B) was fixated: its contact share held
	/// back (D5) and, if withhold, the reaction kept for that end and its push speed noted (D16).
	void handOnChange(const btSolverConstraint& c, btSolverRowKind kind, bool fixA, btScalar change, bool withhold, const btSolverPools& pools);
	/// m_localOf of the layer's free bodies: their index among them (-1 for every other body); and clear it.
	void indexFreeBodies(int layer, const btSolverPools& pools);
	void unindexFreeBodies(int layer);
	/// The layer's rows with one end free and the other immovable (fixated here, or static), grouped
	/// by free body, once per step (call with the layer's fixated inverse masses zeroed).
	void gatherSupportRows(int layer, const btSolverPools& pools);
	/// One sweep of the layer's rows; returns the largest squared change of a row's velocity.
	btScalar sweep(int layer, int iteration, int sweeps, const btSolverPools& pools);
	/// For every free body of the layer, its rows against fixated or static bodies: the load
	/// transfer of the weight pass (btLoadTransfer.h, from the deltas in m_before) or the support
	/// block solve of the up pass (btSupportBlock.h).
	enum btSupportSolve
	{
		BT_SUPPORT_LOAD_TRANSFER,
		BT_SUPPORT_BLOCK
	};
	void solveSupportRows(int layer, const btSolverPools& pools, btSupportSolve solve);
	/// D16 guard: whether the body's weight and the load withheld for it act outside the convex
	/// hull of its support points (statics: it must tip).
	bool loadOutsideSupport(int layer, int node, const btSolverPools& pools, btScalar timeStep, btScalar margin);
	/// Whether the line through body `id`'s centre plus d0 along P meets the plane of its support
	/// points in the layer outside their convex hull (by more than margin of its size).
	bool lineOutsideSupport(int layer, int id, const btVector3& P, const btVector3& d0, btScalar margin, const btSolverPools& pools);
	/// D25: whether the centre of mass of the tipping members from `first` (body `id` first) is
	/// outside body id's support (statics of the sub-stack as one rigid body).
	bool membersOutsideSupport(int layer, int id, int first, const btSolverPools& pools);
	/// D25: free body `local` of the layer tips with the bodies resting on it alone, as one rigid
	/// body (btTippingComposite.h), if statics says the composite tips (D27: for an `impact` load,
	/// the caller's test that the load acts outside the support suffices) and its solve adds no
	/// energy; the members' prior velocities kept in m_tipSaved. False: nothing changed.
	bool tipWithMembers(int layer, int local, int sweeps, const btWeightPassParams& weight, const btSolverPools& pools, int* sweepsRun, bool impact, bool slide = false);
	btAlignedObjectArray<char> m_slidUp;  ///< D29, per solver body: its support friction was at its bound after its layer pass
	/// Per solver body, whether it is in a joint: a joint row of this step touches it, or Bullet
	/// counts a constraint ref (a disabled joint has no rows but keeps its ref). Built in build().
	btAlignedObjectArray<char> m_jointed;
	bool inJoint(int id) const { return id >= 0 && id < m_jointed.size() && m_jointed[id]; }
	/// D32, per solver body: something drives it (a joint holds it, a moving kinematic body
	/// touches it, or it touches a driven body), so its motion is shown to the layer above however
	/// slow. Built in build() by markDriven().
	btAlignedObjectArray<char> m_driven;
	btAlignedObjectArray<int> m_drivenQueue;
	btAlignedObjectArray<int> m_drivenStart;
	btAlignedObjectArray<int> m_drivenAdjacent;
	void markDriven(const btSolverPools& pools);
	bool driven(int id) const { return id >= 0 && id < m_driven.size() && m_driven[id]; }
	int m_rigidSlidingComposites = 0;     ///< D29 composites kept this step
	/// D16/D26: which free bodies of the layer a rejection restores (m_rejectLocal): with perIsland
	/// those in the rejected bodies' islands (components of the contact graph); else all of them.
	void rejectIslands(int layer, bool perIsland);
	/// D25: tipping members [first, end) get their solver deltas from before (m_tipSaved) back.
	void restoreTipMembers(int first, int end, const btSolverPools& pools);
	/// D20: whether every free body's load (in m_before) changes its velocity by at most `speed`
	/// (m/s) at its farthest point, and would change no body it rests on by more (mass ratio).
	bool loadsBelow(int layer, const btSolverPools& pools, btScalar speed);
	/// D20: the layer's support rows take its loads (load transfer) with no re-solve; the changes
	/// are withheld for the layer below.
	void transferOnly(int layer, const btSolverPools& pools);
	/// The mean normal of the body's (solver body id) supports in the layer, unit, pointing into
	/// the body; against gravity where it has none (D16 guard).
	btVector3 supportNormal(int layer, int id, const btVector3& gravity, const btSolverPools& pools);
	/// D29: whether a support friction row of the layer's free body `local` (against its fixated or
	/// static supports; the layer must be fixated) is at its Coulomb bound (99%).
	bool slidesOnSupport(int layer, int local, const btSolverPools& pools);
	/// D29: whether the composite starting at m_tipMembers[first] (the base first) sticks at every
	/// height: the impulses this step (from last step's velocity and this step's forces) of the
	/// members at or above it, summed, have a part across the mean normal of the contacts under
	/// that height within their smallest friction coefficient times the part along it, plus
	/// `slack` (m/s, per unit of the mass above).
	bool membersStick(int first, int mark, btScalar slack, const btSolverPools& pools);
	/// Mark (1) or unmark (0) the layer's lower bodies in m_fixated.
	void markFixated(int layer, char value);
	/// Keep the impulse a row's change owes its fixated end (side A or B) for that body.
	void withholdFromFixated(const btSolverConstraint& row, bool sideA, btScalar impulse);
	bool hasJoints(int layer, const btSolverPools& pools) const { return layer == 0 && m_withJoints && pools.m_joints.size() > 0; }
	/// Friction or rolling-friction rows into the layers of their contact rows.
	void bucketFollowers(const btConstraintArray& rows, const btAlignedObjectArray<int>& contactLayer, btAlignedObjectArray<int>& start,
						 btAlignedObjectArray<int>& sorted);
	bool receiveWithheld(int layer, const btSolverPools& pools);

	template <class Visit>
	void visitLayerRows(int layer, const btSolverPools& pools, Visit visit);

	int m_numLayers = 0;
	int m_jointSweeps = 0;
	bool m_withJoints = true;  // the weight pass leaves joint rows alone
	const btStackLayers* m_layers = 0;
	// Rows per layer (CSR: start offsets of size K + 1, then row indices), per pool.
	btAlignedObjectArray<int> m_contactStart, m_contactRows;
	btAlignedObjectArray<int> m_frictionStart, m_frictionRows;
	btAlignedObjectArray<int> m_rollingStart, m_rollingRows;
	btAlignedObjectArray<int> m_solverBodyOfNode;
	btAlignedObjectArray<int> m_nodeOfSolverBody;

	// Fixation of the current layer.
	btAlignedObjectArray<char> m_fixated;                 // per solver body
	btAlignedObjectArray<btVector3> m_savedInvMass;       // per fixated body of the layer
	btAlignedObjectArray<btFixationBackup> m_backups;     // per row of the layer with a fixated end
	btAlignedObjectArray<btScalar> m_impulseBefore;       // per row of the layer: impulse at the pass start
	struct btBodyDelta
	{
		btVector3 m_deltaLinear;
		btVector3 m_deltaAngular;
		btVector3 m_loadLinear;    // the velocity change the delivered load alone gave the body
		btVector3 m_loadAngular;
	};
	btAlignedObjectArray<btBodyDelta> m_before;           // weight pass: free bodies before their load
	// Load transfer: per solver body its index among the layer's free bodies (-1 otherwise), and
	// the layer's rows with one immovable end grouped by free body (CSR).
	// Gathered once per layer per step (the up pass's block and the weight pass's transfer see the
	// same fixated ends): free body slot m_freeSlot[layer] + i owns m_transferRows[m_supportBegin[slot],
	// m_supportEnd[slot]).
	btAlignedObjectArray<int> m_localOf, m_transferStart, m_transferCursor;
	btAlignedObjectArray<btLoadTransferRow> m_transferRows;
	btAlignedObjectArray<int> m_freeSlot, m_supportBegin, m_supportEnd;
	btAlignedObjectArray<char> m_supportGathered;  // per layer
	btAlignedObjectArray<btScalar> m_loadSpeed;  // D20: per free body of the layer, its load's speed (m/s)

	btAlignedObjectArray<btVector3> m_hull, m_hullChain;  // support points in the plane, their convex hull
	btAlignedObjectArray<btScalar> m_pushSpeed;  // per graph node: fastest approach of a body whose load it got (m/s)
	btWithheldReactions m_withheld;  // per graph node: what fixation kept from it (D13)
	struct btPairLoad
	{
		const void* m_manifold;  // keys only, never dereferenced; checked against the bodies (a pooled
		const void* m_body0;     // manifold may serve another pair next step)
		const void* m_body1;
		btScalar m_total;
	};
	// D18: this step's records (appended per group) and last step's, in last step's order (findPairLoad indexes them on its first miss).
	// Arrays keep their capacity, so a settled world's steps allocate nothing.
	btAlignedObjectArray<btPairLoad> m_pairLoadsThisStep, m_pairLoadsLastStep;
	/// Last step's load of the pair, or 0. hint: the manifold's place in this step's order of
	/// look-ups (groups and their manifolds in turn), where a step like the last finds it at once;
	/// elsewhere a hash table of last step's records by manifold (built once per step, on the
	/// first miss; it keeps its capacity) is probed.
	const btPairLoad* findPairLoad(const void* manifold, int hint);
	btAlignedObjectArray<int> m_pairLoadTable;  ///< record index per slot, -1: empty
	bool m_pairLoadsIndexed = false;
	int m_pairLoadCursor = 0;  ///< manifolds of this step's earlier groups (restorePairLoads' hints)
	// D24: per free-body slot, the factor its support block kept for the weight pass (valid: 1).
	btAlignedObjectArray<btCholesky6> m_blockFactor;
	btAlignedObjectArray<char> m_blockFactorValid;
	bool m_shareFactor = false;
	int m_sharedFactorTransfers = 0;
	// D25: this layer's tipping composites (members, base first), per solver body its composite + 1.
	btAlignedObjectArray<int> m_tipMembers, m_tipFirst, m_tipBase, m_tipOf;
	/// membersStick's scratch: one entry per member above the base.
	struct btStickLevel
	{
		int m_height;
		btScalar m_mass;      ///< kg
		btVector3 m_impulse;  ///< m dv this step (N s)
		btVector3 m_normal;   ///< its contacts on members below, normals summed
		btScalar m_mu;        ///< their smallest friction coefficient
	};
	btAlignedObjectArray<btStickLevel> m_stickLevels;
	btAlignedObjectArray<char> m_tipSlides;  ///< D29: per composite of the layer, whether a sliding body formed it
	// D25: per solver body its contact rows, as positions in m_contactRows in ascending order (CSR,
	// built on the first gathering of a step), and the gathering's queue of positions (a min-heap).
	void buildRowsOfBody(const btSolverPools& pools);
	/// Calls visit(row, r) for each contact row of `layer` with solver body `id` at one end, in the
	/// layer's order (r: the row's position, as m_rowUpper and m_rowLower index it).
	template <class Visit>
	void visitBodyRows(int id, int layer, const btSolverPools& pools, Visit visit);
	btAlignedObjectArray<int> m_rowsOfBodyStart, m_rowsOfBody, m_tipQueue;
	/// With m_rowsOfBody: the higher and the lower of the two solver bodies of each contact
	/// position (by stack height; -1 where the heights are equal or an end is no graph node: no
	/// body can rest on the other there), and per solver body whether it may join a tipping composite (a dynamic body,
	/// in no joint, with unit linear and angular factors), so the composite's walk queues only the
	/// rows that can add a member and reads no row or body it skips.
	btAlignedObjectArray<int> m_rowUpper, m_rowLower;
	btAlignedObjectArray<char> m_tipEligible;
	bool m_rowsOfBodyBuilt = false;
	btAlignedObjectArray<char> m_rejectLocal;  // D26: per free body of the layer, its island was rejected
	btAlignedObjectArray<int> m_rejectedComponents;
	btAlignedObjectArray<btBodyDelta> m_tipSaved;  // per tipping member, its solver deltas before
	// D25: per solver body, the load a rejected weight-pass layer gave back this step (velocity
	// change, linear and angular); a tipping composite that takes the body in takes its momentum.
	btAlignedObjectArray<btVector3> m_discardedLinear, m_discardedAngular;
	btAlignedObjectArray<int> m_discardedIds;  // the solver bodies given some this step (cleared at the pass's end)
	int m_tippingComposites = 0;
	btAlignedObjectArray<int> m_scratchLayer, m_scratchFollow, m_scratchCursor;  // build(), kept so steps do not allocate
	// Per contact row, its point as the step began, read once in row order (build()): whether it
	// carried impulse last step (the support block's rest test) and its felt share (D5).
	btAlignedObjectArray<char> m_pointCarried;
	btAlignedObjectArray<btScalar> m_pointFelt;
	// D23: this group's composites (every layer's), their members (base first), the layer's active
	// ones and per solver body the active composite (-1: none); per friction row its slip at setup.
	btAlignedObjectArray<btSlidingComposite> m_composites;
	btAlignedObjectArray<int> m_compositeMembers;
	btAlignedObjectArray<int> m_active;
	btAlignedObjectArray<int> m_compositeOf;
	btAlignedObjectArray<char> m_slipsAtSetup;
	btAlignedObjectArray<char> m_inComposite;  // per solver body, scratch of formComposites
	btAlignedObjectArray<char> m_carried;      // per solver body: in a composite's sub-stack this step
};

#endif  // BT_SHOCK_PROPAGATION_LAYERED_PASSES_H
