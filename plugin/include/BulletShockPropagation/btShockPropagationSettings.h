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

#ifndef BT_SHOCK_PROPAGATION_SETTINGS_H
#define BT_SHOCK_PROPAGATION_SETTINGS_H

#include "LinearMath/btScalar.h"

/// Iteration counts that follow the app: a sweep count set to this takes the world's
/// btContactSolverInfo::m_numIterations at each step (see btShockPropagationSettings).
enum
{
	BT_SHOCK_ITERATIONS_FROM_WORLD = -1
};

/// What a fixated (infinite-mass) body looks like to the layer above it (decision D1).
enum btShockPropagationFixationMode
{
	/// Infinite mass, full rigid motion kept (linear and angular velocity, including what the
	/// layers below gave it this step). Measured: at 10 sweeps the tilt noise PGS leaves in each
	/// layer of the 200-brick wall climbs the wall (3.1 cm drift in 10 s; docs/design.md, D1).
	BT_FIXATION_KEEP_VELOCITY = 0,
	/// Infinite mass and zero velocity, as in Erleben's OpenTissue code (set_fixed).
	BT_FIXATION_ZERO_VELOCITY = 1,
	/// Infinite mass, linear velocity kept, angular velocity treated as zero (the default before
	/// the one-setup step; kept to reproduce the measurements in docs/design.md, D1).
	BT_FIXATION_KEEP_LINEAR_VELOCITY = 2,
	/// Infinite mass; joints see the full rigid motion; contacts see the linear velocity and the
	/// spin about their normal, but not the tilt (rotation about axes across the normal). A stack
	/// on a turntable turns with it, a chain swings, and the tilt noise of an unconverged layer
	/// does not move the contact points of the layer above along their normals. Default (D1).
	BT_FIXATION_KEEP_LINEAR_AND_TWIST = 3
};

/// Switches and constants that exist to reproduce the measurements behind the design decisions
/// (ablations: turn a decision off and see what it was for) and the guards' scales. Each is set
/// to the value docs/design.md measured; apps are not expected to change them.
struct btShockPropagationDiagnostics
{
	/// Solve the second correction layer by layer (bottom-up, lower bodies fixated) instead of as
	/// one global projection with every body free (the paper's form, which squeezes mass-ratio
	/// stacks apart at 10 sweeps; D4).
	bool m_layeredSecondCorrection = true;

	/// The second phase's collision detection (D4, world mode): after the positions advance, a
	/// real collision detection at t + dt (Bullet's broadphase and dispatcher, new pairs included)
	/// finds the contacts the second correction removes. Off: the step's own contact points, their
	/// depths recomputed from the new transforms (the depth refresh of before issue 38, which
	/// misses every contact that appears during the step).
	bool m_secondDetection = true;

	/// The second detection dispatches every overlapping pair, not only the pairs with a body in a
	/// stacked island of the step (an island holding a body at stack height 2 or more). Off
	/// (default): a step without stacks runs no second detection at all, so scenes without stacks
	/// cost what they cost before.
	bool m_secondDetectionAllPairs = false;

	/// D14 (beyond the paper): a fixated body that moves into a free one above it pushes it at most
	/// at the common velocity of an inelastic collision of the two (row effective masses), not at
	/// its own speed. A support heavier than its load is unaffected; without it a light body thrown
	/// into a heavy one throws the heavy one at its own speed (hostile worlds, 1e-3 to 1e6 kg:
	/// a 2.7 g box squeezed under a 331 t one threw it at 4 m/s; docs/design.md).
	bool m_inelasticFixation = true;

	/// Fraction (unitless, 0..1] of each measured penetration removed by a correction. 1 removes
	/// all of it, as OpenTissue's correction() does (erp = 1).
	btScalar m_correctionFraction = btScalar(1);

	/// The world's second phase (D4) runs m_secondPhaseRounds rounds of detection and correction
	/// at t + dt; every round but the last removes this fraction (unitless, 0..1] of each depth
	/// beyond the slop, the last removes all of it. A full first round pushes bodies into
	/// contacts it cannot see yet (100 cubes into a pit, 3 s, seeds 1-4: one round at 1 leaves
	/// the deepest at 324 mm, two rounds at 0.8 then 1 at 132 mm, the phase off 239 mm).
	btScalar m_secondCorrectionFraction = btScalar(0.8);

	/// Rounds of the second phase (count, >= 1): the second round's detection sees what the first
	/// round's correction moved bodies into (docs/design.md, D4).
	int m_secondPhaseRounds = 2;

	/// Two friction rows per contact point (a four-sided friction pyramid) in stacked groups,
	/// instead of Bullet's default one velocity-aligned row. Bullet's single row lets towers creep
	/// sideways (docs/design.md, D7). Groups without stacks keep the app's m_solverMode.
	bool m_twoFrictionDirections = true;

	/// Layered solve also when the contact graph has a single layer (no stacks). Off: such groups
	/// are solved by Bullet's own solver with the app's settings, so scenes without stacks behave
	/// and cost exactly as stock Bullet.
	bool m_layerFlatGroups = false;

	/// Order the stack layers by support as well as by BFS distance (btStackLayers): a body that
	/// rests on another (mean contact normal within m_supportAngle of the up direction, up =
	/// -gravity) is put above it. Off: Erleben's plain BFS layers, which clamp the top box of the
	/// taller column of a door between two fixated bodies (D12).
	bool m_supportOrdering = true;

	/// Largest angle (radians) between a contact normal and the up direction for which the
	/// contact counts as support; steeper contacts are side contacts. 1.0472 = 60 degrees.
	btScalar m_supportAngle = btScalar(1.0471975511965976);

	/// Largest warm start of a contact in a stacked group, in weight impulses m g dt of its lighter
	/// body (unitless). Bullet warm-starts from last step's impulse; under fixation a heavy body
	/// resting on a light one leaves its own weight there, which flings the light body when their
	/// roles change (D5, measured in docs/design.md). Equal masses (every registry scene) keep up
	/// to this many bodies' weight.
	btScalar m_warmStartWeights = btScalar(16);

	/// How much of a contact's cached impulse its lower body gets back at the next warm start
	/// beyond the share it felt (unitless, 0..1; D5). A layer pass applies its impulse changes to
	/// the upper body only, so a contact's total T is more than its lower body felt (F). 0 restarts
	/// each step from the state the last one ended in (Erleben's layered solution): the seesaw's
	/// plank then turns at a constant 0.005 rad/s and never tips. 1 is Bullet's coupled warm start,
	/// F = T: the unfelt parts pile up on the lower bodies and large stacks creep (pyramid of base
	/// 40: 0.89 cm in 10 s). Measured window (docs/design.md): 0.15 does not tip the seesaw within
	/// 4 s, 0.25 lets the 9,870-box pyramid creep from 8 s; 0.2 does neither.
	btScalar m_warmStartCoupling = btScalar(0.2);

	/// D16: before its layer's re-solve, a body's support rows take the load handed down to it in
	/// one least-squares step (btLoadTransfer), instead of sweep by sweep. Without it the share
	/// PGS leaves after N sweeps is handed down through every layer below and comes back the
	/// next step (measured in docs/design.md, D16: a pyramid of base 12 diverges at 10 sweeps).
	bool m_loadTransfer = true;

	/// D19: before a layer's sweeps, each free body's rows against its fixated or static supports
	/// are solved as one block (a 6 x 6 least-squares solve of the rows' velocity errors, the
	/// smallest impulses that give it, projected onto the rows' limits and kept only if it lowers
	/// the rows' PGS objective). A resting layer then converges within m_layerMinIterations
	/// sweeps where PGS alone needs all N. Off with early-ending layers, the tower of 40 falls in
	/// float (0.78 s) and creeps in double (measured in docs/design.md, D19).
	bool m_supportBlocks = true;

	/// D31: a weight-pass re-solve ends with the same block solve (D19) of each free body's
	/// support rows, after its sweeps. Its sweeps stop once one changes no row's velocity by more
	/// than the convergence speed, which leaves PGS's error (the rows swept last exact, the others
	/// not) as a small spurious turn of each body; nothing restores an orientation error below the
	/// correction's slop, and in tall pyramids the next steps turned it into more (the 2-D pyramid
	/// of base 80 moved at 0.87 s, base 140 at 0.68 s; with the block base 80 stands to 4.9 s and
	/// base 140 for 3 s; measured in docs/design.md, D31). Needs m_supportBlocks.
	bool m_weightPassBlocks = true;

	/// D32: a fixated body's motion along a contact row (what its fixation mode shows the layer
	/// above, D1) is shown only if it is at least the convergence speed (m_weightConvergence |g| dt,
	/// 0.98 mm/s at 9.81 m/s^2 and 60 Hz) or something drives the body (a joint holds it, a moving
	/// kinematic body touches it, or it touches a driven body); slower, the row sees the support at
	/// rest. The sweeps end once they change no row by more than that speed, so an undriven
	/// support's motion below it is the solve's error, and handed up it turned the pyramids' small
	/// tilts into an instability (the 2-D pyramid of base 80 moved at 4.9 s at 10 iterations and
	/// 1.9 s at 3; with this it stands 10 s at 3-20 iterations; measured in docs/design.md, D32).
	/// Joint rows always see the full motion.
	bool m_fixationRestSpeed = true;

	/// D24: the weight pass's load transfer (D16) of a body solves with the factor its support
	/// block (D19) made of the same rows this step (every row in the block) instead of forming and
	/// factoring its own: one 6 x 6 factorisation per body and step where there were two. The same
	/// least-norm transfer without the transfer's small regularising shift (measured in
	/// docs/design.md, D24). Off: each factors its own.
	bool m_sharedBlockFactor = true;

	/// D20: a weight-pass layer whose loads all change its free bodies' velocities by at most the
	/// convergence speed (m_weightConvergence |g| dt; linear change plus angular change times the
	/// shape's bounding radius) is not re-solved: its support rows take the loads in one
	/// least-squares step (m_loadTransfer) and the changes are handed on to the layer below, as a
	/// re-solve that converged before its first sweep would. Saves the layer's fixation and sweep
	/// where a settled stack hands down only bookkeeping (measured in docs/design.md, D20).
	bool m_transferSmallLoads = true;

	/// D21: the global pass ends once one of its sweeps changes the rows' velocities by at most
	/// the convergence speed (m_weightConvergence |g| dt) in total (the square root of the sum of
	/// squares Bullet's sweep returns, so no row changed by more), at least one sweep, at most
	/// ceil(f N). A warm-started stack at rest converges in its first sweep; a moving scene runs
	/// them all. Off: always ceil(f N) sweeps (measured in docs/design.md, D21).
	bool m_convergedGlobalPass = true;

	/// D23 (opt-in): a free body whose support friction is at its Coulomb limit and slips (by more
	/// than m_compositeSlip |g| dt, at the step's start and after the global pass) carries the
	/// inertia of everything resting on it: its friction rows are swept with the mass of that
	/// sub-stack, which moves with it across the support, in the layer pass and in the weight
	/// pass. On, a stack sliding down a ramp gains the momentum of kinetic friction (within 1.3%;
	/// off, 6-25% short) and a pushed stack's base mostly keeps with the boxes above (it can still
	/// run away). Off by default because hostile worlds exceed their energy or speed bounds more
	/// often with it (1,000 seeds: 10 against 7 in float, 11 against 8 in double; measured in
	/// docs/design.md, section 4h).
	bool m_slidingComposites = false;

	/// D25: where the weight pass finds that statics makes a body tip (its weight and the loads
	/// resting on it act outside its support points' hull) and its re-solve sped it up beyond its
	/// push, the body and everything resting on it alone are merged into one rigid body (momentum
	/// and angular momentum kept) and its support rows are solved for that body, instead of the
	/// body turning alone under the whole weight above it (or the guard holding it up).
	bool m_tippingComposites = true;

	/// D26: a weight-pass re-solve the guard rejects restores only the free bodies of its layer in
	/// the rejected body's island (its connected component of the contact graph), not every free
	/// body of the layer. Bullet solves small islands in one batch, so one layer can hold bodies of
	/// many independent stacks: off, one stack's rejection held up every other stack of the batch.
	bool m_rejectPerIsland = true;

	/// D27: where the load handed to a body is an impact (it changes the body's velocity by more
	/// than m_weightGuardTipping |g| dt: something landed on what rests on it), D25's composite
	/// forms wherever that load acts outside the body's support, without D25's test that the
	/// composite's own weight does: a box landing on an overhanging staircase turns the part above
	/// the hinge it cannot be carried past, as its momentum says, though the part's weight alone
	/// would be carried. Off, the landing is stopped as if the staircase could not turn.
	bool m_impactTipping = true;

	/// D28: the weight-pass guard (D16) judges a re-solve that did not converge by the speed of the
	/// body's kinetic energy, sqrt(2 E / m), spin included, not by its centre of mass's speed
	/// alone: an unconverged re-solve that left a light body under a heavy load spinning at any
	/// rate passed the guard (hostile worlds: a 10 g cube at 1.3e7 rad/s, then at 3e5 m/s).
	bool m_guardSpin = true;

	/// D29: a body that slides carries what rests on it, as one rigid body. Where a body's support
	/// friction is at its Coulomb bound after its layer pass and again after its weight-pass
	/// re-solve, the body and everything resting on it are merged and solved as D25's composite
	/// (without D25's tipping statics), provided every member can stick to what carries it (the
	/// tangential velocity change it gets is within its contacts' friction coefficient times the
	/// normal one). Layered fixation gives a sliding body no inertia from what it carries: the
	/// bodies above are dragged to its velocity, then their reaction slows it alone, and a top-down
	/// pass over layers diverges by the ratio of the carried mass to the body's own. Off, a pushed
	/// stack of 5 accelerates at 1.7-2.9 m/s^2 where Coulomb says 1.96; on, at 1.84-2.11 (docs/design.md,
	/// D29). With it, a composite's solve is kept if it leaves the merged body with no more kinetic
	/// energy than before or than its motion without the support rows (D25 alone: before).
	bool m_rigidSlidingComposites = true;

	/// D30, as a share of |g| dt^2 (unitless): how far outside the face below a box corner may be and
	/// still be kept as a contact point by m_keepBoxFaceCorners (27 micrometres at 9.81 m/s^2 and
	/// 60 Hz; the corners Bullet's box-box test dropped under a sliding stack were 6 micrometres out
	/// at most, docs/design.md, D30). Inside the face a corner is kept down to the manifold's
	/// breaking threshold.
	btScalar m_boxFaceReachPerFall = btScalar(0.01);

	/// D23, as a share of |g| dt (unitless): the slip speed of a sliding support (1 cm/s at
	/// 9.81 m/s^2 and 60 Hz, ten times the convergence speed m_weightConvergence), and the largest
	/// velocity change across the support that the load handed down to a composite's base may make
	/// before the composite is dropped for that step (the sub-stack did not move with its base).
	btScalar m_compositeSlip = btScalar(0.06);

	/// D16 convergence test of a weight-pass re-solve, as a share of |g| dt (unitless): a re-solve
	/// whose last sweep changed no row's velocity by more than this has converged and stands
	/// (1 mm/s at 9.81 m/s^2 and 60 Hz).
	btScalar m_weightConvergence = btScalar(0.006);

	/// Weight pass guard (D16), as a share of |g| dt (unitless): a load handed down cannot push a
	/// body faster than the bodies that pressed it on it were moving towards it (an inelastic
	/// push) plus this slack. A re-solve that leaves a body faster could not carry its load
	/// within its sweeps; the layer keeps its state from before the load and hands nothing on (it
	/// sags; it never gains energy). Measured in docs/design.md, D16.
	btScalar m_weightGuardSlack = btScalar(0.1);

	/// Weight pass guard (D16, D17), in steps of free fall |g| dt (unitless): if its re-solve
	/// converged, a body may be sped up by this much more when it tips where statics says it must
	/// (its weight and the normal load of the contacts resting on it act outside the convex hull of
	/// its support points, by m_weightGuardTipMargin; it pivots rather than sinks) or when it slides
	/// (D17: along its supports' tangent plane by no more than the load's own tangential part, with
	/// no sinking or lifting off). 0 turns both off (the leaning tower only sags, a dragged stack
	/// stops); measured in docs/design.md, D16 and D17.
	btScalar m_weightGuardTipping = btScalar(3);

	/// The D16 statics test's margin, as a share of the support's size (unitless): how far outside
	/// the hull of its support points a load must act before a body is taken to tip. 0 (default
	/// since D19): statics as it is. Before D19 the up pass left unconverged loads at the bricks'
	/// edges and 0.1 was needed (at 0.01 the round tower at 100 iterations fell); with converged
	/// layers 0, 0.01, 0.02 and 0.05 hold every stack, and 0.1 kept a stack that must fall (the
	/// truth suite's d = 0.3, n = 4) standing (docs/design.md, D19).
	btScalar m_weightGuardTipMargin = btScalar(0);

	/// Warm-start factor of stacked groups (unitless, 0..1). Bullet scales each contact's cached
	/// impulse by the app's m_warmstartingFactor (0.85 by default), a damping for plain PGS. Here
	/// the layered passes would then push 15% of every load through every layer again each step,
	/// and at 10 sweeps the wall and the pyramid of base 30 diverge (D16, measured). 1 (default)
	/// starts from the impulses the last step ended with; negative: the app's factor. Groups
	/// without stacks, and the classic method (m_weightFeeling off), use the app's. Warm starting
	/// off in the app stays off.
	btScalar m_warmStartFactor = btScalar(1);

	/// The velocity step of stacked groups (docs/design.md, section 4u): Bullet's setup with every
	/// row from zero (a row past the fixation limit warm, as stock starts it), the
	/// shock-propagation predictor (btShockPredictor: fixated up pass, weight-feeling down pass,
	/// every withheld impulse delivered, each cycle line searched on its kinetic energy), Bullet's
	/// own sweeps as the corrector (ceil(f N), ended once converged), Bullet's finish, the layered
	/// position correction. Momentum is conserved by construction; it holds the 26 truths at 5,
	/// 10 and 20 iterations. On (the default); off selects the layered passes of sections 4a-4t,
	/// which are being removed (the converging-solver issue). In piles it costs more than the
	/// layered passes did (the pit of 100 cubes about 10x stock against their 3.5x).
	bool m_convergingStep = true;

	/// The converging step's predictor: a layer ends once a sweep moves no row's bodies by more
	/// than this share of |g| dt along the row (unitless; 6e-6 = 1 micrometre/s at 9.81 m/s^2 and
	/// 60 Hz). A layer's leftover error is handed to the next one: at 6e-4 (0.1 mm/s) the tower of
	/// 20 moves at 3.6 s, at 6e-6 it stands (docs/design.md, section 4u).
	btScalar m_predictorConvergence = btScalar(6e-6);

	/// Most sweeps of each layer in each of the converging step's predictor passes (count).
	int m_predictorIterations = 200;

	/// Most up-and-down cycles of the converging step's predictor (count): a cycle after the first
	/// starts each layer from the final motion of the layers below it, each cycle is line searched
	/// on its own, and the cycles end once no layer needs a second sweep. 4: all 156 truth runs
	/// (26 truths at 5, 10, 20 iterations, world and solver-only; float and double); float with
	/// 3, 5, 6, 8: 153, 153, 156, 154, the pushed stack's boxes parting by 1.0-1.5 cm (section 4u).
	int m_predictorCycles = 4;

	/// The converging step's cycles after the first end their layer visits at this share of the
	/// last cycle's coupled residual (unitless; never below m_predictorConvergence's speed): an
	/// inexact solve, as far as the outer error warrants. At 0.1 the ledge column tips 11-13%
	/// faster than rigid-body dynamics says, at 0.01 4% (exact: 3%); the pit costs 11.9 times
	/// stock against 14.8 with exact visits (docs/design.md, section 4u).
	btScalar m_predictorForcing = btScalar(0.01);
};

/// What users tune, with its default, unit and reason (the diagnostics switches are in
/// m_diagnostics). Defaults are set here only.
///
/// What comes from the app (btContactSolverInfo of the world, read at every step): the time
/// step, m_numIterations (the sweep counts below follow it by default), the residual threshold
/// (ends the global pass early), warm starting and its factor, SOR, joint ERP/CFM, restitution
/// and friction settings, m_solverMode. Bullet's rows are set up once per step with the app's
/// time step exactly as a stock step sets them up, and finished once (D15). Replaced while the
/// plugin solves a stacked group: Baumgarte on contacts (m_erp2) and split impulse, by the
/// position correction (D6). Groups without stacks are solved by Bullet's own solver, unchanged.
struct btShockPropagationSettings
{
	/// Weighting value f in [0, 1] (unitless): the share of the app's sweeps spent on the global
	/// pass, where every body is free, before the layers are solved bottom-up with the lower
	/// bodies fixated. The global pass lets the lower bodies feel the weight of the upper ones;
	/// the layered pass makes the stack rigid. f = 0 skips the global pass (Erleben's classic
	/// method, the paper's f). Default 0.5 (D2, measured in docs/design.md).
	btScalar m_weighting = btScalar(0.5);

	/// PGS sweeps of the global pass (count). BT_SHOCK_ITERATIONS_FROM_WORLD (default):
	/// ceil(f * m_numIterations) of the world's solver info, at least 1 when f > 0 (D7).
	int m_globalIterations = BT_SHOCK_ITERATIONS_FROM_WORLD;

	/// PGS sweeps of each layer (count). BT_SHOCK_ITERATIONS_FROM_WORLD (default): the world's
	/// m_numIterations, at least m_layerIterationFloor. A layer is one contact deep, so its sweeps converge it where a whole
	/// stack would need O(n^2); each row is in one layer, so the layered pass costs about one
	/// stock solve (D7).
	int m_layerIterations = BT_SHOCK_ITERATIONS_FROM_WORLD;

	/// Fewest sweeps a layer may run before it is cut off unconverged (count, D22), when
	/// m_layerIterations comes from the world: a layer sweeps at most max(N, this). A layer ends
	/// once converged (m_layerMinIterations), so this only lets an unconverged layer of an app
	/// with few iterations (BenchmarkDemo: 5) finish its sub-problem; joint rows keep the app's
	/// N. Default 10, Bullet's own default N: at 5 iterations the 1000 stack then holds (0.02 cm
	/// in 10 s instead of creeping 1.65 cm) at 25% less cost (measured in docs/design.md, D22).
	/// 0: the app's N.
	int m_layerIterationFloor = 10;

	/// Fewest PGS sweeps of each layer (count, D19): after them a layer ends as soon as a sweep
	/// changes no row's velocity by more than the convergence speed (m_weightConvergence |g| dt,
	/// 1 mm/s at 60 Hz), and runs m_layerIterations at most. Default 2 (with 1 the card house
	/// collapses, 93 cm at 7.4 s; measured in docs/design.md, D19).
	/// BT_SHOCK_ITERATIONS_FROM_WORLD (-1): no early end, always m_layerIterations.
	int m_layerMinIterations = 2;

	/// Projected Gauss-Seidel sweeps of each position correction (count).
	/// BT_SHOCK_ITERATIONS_FROM_WORLD (default): the world's m_numIterations.
	int m_correctionIterations = BT_SHOCK_ITERATIONS_FROM_WORLD;

	/// World mode (btShockPropagationDynamicsWorld; D4): after Bullet integrates the positions,
	/// the paper's second phase, "collision detection at t + dt; correction()": Bullet's
	/// broadphase and dispatcher find the contacts at the new positions (new pairs and new points
	/// included), and the stacked components' penetration beyond the slop is removed by the
	/// layered position correction (lower bodies fixated). Velocities are not touched. What an app
	/// sees of it (callbacks, applied impulses, manifolds): the world's header. The solver-only
	/// mode cannot run it (a constraint solver is called before the positions advance). Default on
	/// since issue 38; off, the world steps exactly as btDiscreteDynamicsWorld with the plugin's
	/// solver.
	bool m_secondCorrection = true;

	/// See btShockPropagationFixationMode (D1).
	btShockPropagationFixationMode m_fixationMode = BT_FIXATION_KEEP_LINEAR_AND_TWIST;

	/// Penetration left in place by corrections (metres). Negative (default): scaled from the
	/// world, m_correctionSlopPerFall * |g| dt^2 (0.5 mm at 9.81 m/s^2 and 60 Hz). 0 is
	/// OpenTissue's choice; in Bullet it leaves resting boxes at zero distance, where the box-box
	/// test may report no contact, so the next step sees a gap and the body falls into it again.
	btScalar m_correctionSlop = btScalar(-1);

	/// The derived slop as a share of the distance a body falls from rest in one step, |g| dt^2
	/// (unitless). 0.18 gives the 0.5 mm measured at 60 Hz (docs/design.md, D6), and scales with
	/// the world's units and rate.
	btScalar m_correctionSlopPerFall = btScalar(0.18);

	/// Weight feeling (D13, D16; in the spirit of Xiong et al., "Two-Pass Shock Propagation", SCA
	/// 2025): after the bottom-up layer pass, a top-down pass hands each layer's impulses, which
	/// fixation withheld from the bodies below, to those bodies, whose support rows take the load
	/// on (m_loadTransfer) before their layer is re-solved. The ground carries the whole stack,
	/// friction capacity is that of the whole weight, and a load past a support's edge tips it.
	/// Default on; off gives Erleben's classic method (lower bodies never feel the upper ones).
	bool m_weightFeeling = true;

	/// Most PGS sweeps of each layer's re-solve in the weight pass (count); a layer stops as soon as
	/// it has converged (m_weightConvergence). BT_SHOCK_ITERATIONS_FROM_WORLD (default): 3 times the
	/// world's m_numIterations. A load past a support's edge takes more sweeps to settle than a
	/// carried one: at 10, the guard held BenchmarkDemo's leaning columns up (D16, measured).
	int m_weightIterations = BT_SHOCK_ITERATIONS_FROM_WORLD;

	/// D30: in a stacked group, a box resting face down on another box keeps the corners of its
	/// face that lie on the other face (at most m_diagnostics.m_boxFaceReachPerFall |g| dt^2
	/// outside it, or inside it) as contact points, where Bullet's box-box test reported only some of them (it keeps only
	/// corners that penetrate; a resting face's corners sit at micrometres, either side). While a
	/// pair's points persist this adds nothing; once a box slides farther per step than its
	/// manifold's breaking threshold (1.5 cm for a 1 m box) every point is new every step and on
	/// about every other step one edge was missing, so the box pivoted and threw what it carried
	/// off. Off: a pushed stack of 5 ends 13-26 cm apart where it must slide as one (1 cm);
	/// on: 0.02-0.96 cm (docs/design.md, D30). Groups without stacks keep Bullet's points.
	bool m_keepBoxFaceCorners = true;

	/// Ablation switches and guard scales (see btShockPropagationDiagnostics); leave as they are
	/// unless reproducing docs/design.md.
	btShockPropagationDiagnostics m_diagnostics;
};

#endif  // BT_SHOCK_PROPAGATION_SETTINGS_H
