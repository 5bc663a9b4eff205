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

/// The solver's fixed numerical thresholds: not settings (nothing changes them), listed here so
/// that every constant of the step is in this header with its unit and its reason.
struct btShockPropagationNumerics
{
	/// Pivot (unitless, of a Jacobi-scaled 6 x 6 factor: each pivot over its diagonal) above which
	/// a body's support rows count as fixing a direction: the span test of grounding and clusters,
	/// the welds and a fixated body's mobility (docs/design.md, section 4.2).
	static btScalar spanMinPivot() { return btScalar(1e-3); }
	/// The same pivot for a support block: its rows are solved at once only where they span all
	/// six directions (docs/design.md, section 4.5).
	static btScalar blockMinPivot() { return btScalar(1e-3); }
	/// Largest cluster (bodies) whose rows are tested together for grounding: (6 n)^3 / 6 = 9.4e6
	/// multiply-adds at 64, about the capped sweeps' cost over its rows (docs/design.md, 4.2).
	static int maxClusterBodies() { return 64; }
	/// Cosine (unitless) within which a face counts as facing a contact normal: a box face whose
	/// corners are kept (D30), a face or a mesh triangle whose normal a resting patch takes (D33;
	/// docs/design.md, section 11).
	static btScalar faceAlignment() { return btScalar(0.99); }
};

/// Switches and constants that exist to reproduce the measurements behind the design decisions
/// (ablations: turn a decision off and see what it was for) and the solver's tolerances. Each is
/// set to the value docs/design.md measured; apps are not expected to change them.
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

	/// D30 and D33, as a share of |g| dt^2 (unitless): how far outside the face below a box corner
	/// (or a face's rim point) may be and still be kept as a contact point by m_keepBoxFaceCorners (27 micrometres at 9.81 m/s^2 and
	/// 60 Hz; the corners Bullet's box-box test dropped under a sliding stack were 6 micrometres out
	/// at most, docs/design.md, D30). Inside the face a corner is kept down to the manifold's
	/// breaking threshold.
	btScalar m_boxFaceReachPerFall = btScalar(0.01);

	/// The corrector's convergence test, as a share of |g| dt (unitless): its sweeps end once one
	/// changes Bullet's residual (the sum of the rows' squared velocity changes) by no more than
	/// this speed squared (1 mm/s at 9.81 m/s^2 and 60 Hz). The velocity error the step accepts,
	/// so also the position correction's tolerance: a contact deeper than the slop by no more than
	/// this speed times dt (16 micrometres at 60 Hz) is not corrected (docs/design.md, section 7).
	btScalar m_weightConvergence = btScalar(0.006);

	/// The predictor: a layer visit ends once a sweep moves no row's bodies by more
	/// than this share of |g| dt along the row (unitless; 6e-6 = 1 micrometre/s at 9.81 m/s^2 and
	/// 60 Hz). A layer's leftover error is handed to the next one: at 6e-4 (0.1 mm/s) the tower of
	/// 20 moves at 3.6 s, at 6e-6 it stands (docs/design.md, section 4.4).
	btScalar m_predictorConvergence = btScalar(6e-6);

	/// Most sweeps of each layer visit of the predictor (count).
	int m_predictorIterations = 200;

	/// Most up-and-down cycles of the predictor (count): a cycle after the first
	/// starts each layer from the final motion of the layers below it, each cycle is line searched
	/// on its own, and the cycles end once no layer needs a second sweep. 4: all 156 truth runs
	/// (26 truths at 5, 10, 20 iterations, world and solver-only; float and double); float with
	/// 3, 5, 6, 8: 153, 153, 156, 154, the pushed stack's boxes parting by 1.0-1.5 cm (docs/design.md, section 4.7).
	int m_predictorCycles = 4;

	/// The predictor's cycles after the first end their layer visits at this share of the
	/// last cycle's coupled residual (unitless; never below m_predictorConvergence's speed): an
	/// inexact solve, as far as the outer error warrants. At 0.1 the ledge column tips 11-13%
	/// faster than rigid-body dynamics says, at 0.01 4% (exact: 3%); the pit costs 11.9 times
	/// stock against 14.8 with exact visits (docs/design.md, section 4.7).
	btScalar m_predictorForcing = btScalar(0.01);
};

/// What users tune, with its default, unit and reason (the diagnostics switches are in
/// m_diagnostics). Defaults are set here only.
///
/// What comes from the app (btContactSolverInfo of the world, read at every step): the time
/// step, m_numIterations (the sweep counts below follow it by default), the residual threshold
/// (ends the corrector early), warm starting (rows past the fixation limit and groups without
/// stacks), SOR, joint ERP/CFM, restitution and friction settings, m_solverMode. Bullet's rows
/// are set up once per step with the app's time step exactly as a stock step sets them up, and
/// finished once. Replaced while the
/// plugin solves a stacked group: Baumgarte on contacts (m_erp2) and split impulse, by the
/// position correction (D6). Groups without stacks are solved by Bullet's own solver, unchanged.
struct btShockPropagationSettings
{
	/// Weighting value f in [0, 1] (unitless): the corrector, Bullet's own sweeps with every body
	/// free after the shock-propagation predictor, runs at most ceil(f N) of them (N the app's
	/// m_numIterations), ended once converged. f = 0 runs none: the predictor's answer stands
	/// (the paper's f, which there weighted a global pass before the layers). Default 0.5.
	btScalar m_weighting = btScalar(0.5);

	/// Most corrector sweeps (count). BT_SHOCK_ITERATIONS_FROM_WORLD (default):
	/// ceil(f * m_numIterations) of the world's solver info, at least 1 when f > 0.
	int m_globalIterations = BT_SHOCK_ITERATIONS_FROM_WORLD;

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

	/// Penetration left in place by corrections (metres). Negative (default): scaled from the
	/// world, m_correctionSlopPerFall * |g| dt^2 (0.5 mm at 9.81 m/s^2 and 60 Hz). 0 is
	/// OpenTissue's choice; in Bullet it leaves resting boxes at zero distance, where the box-box
	/// test may report no contact, so the next step sees a gap and the body falls into it again.
	btScalar m_correctionSlop = btScalar(-1);

	/// The derived slop as a share of the distance a body falls from rest in one step, |g| dt^2
	/// (unitless). 0.18 gives the 0.5 mm measured at 60 Hz (docs/design.md, D6), and scales with
	/// the world's units and rate.
	btScalar m_correctionSlopPerFall = btScalar(0.18);

	/// Weight feeling (in the spirit of Xiong et al., "Two-Pass Shock Propagation", SCA 2025): each
	/// predictor cycle's fixated up pass is followed by a down pass that sweeps each layer again,
	/// top to bottom, after the reactions withheld from its bodies were delivered to them, so a
	/// body meets the load of what rests on it within the cycle. Default on. Off: Erleben's
	/// classic order, every reaction delivered after the up pass and met in the next cycle (up to
	/// 2 K cycles for K layers); both conserve momentum.
	bool m_weightFeeling = true;

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

	/// D33: in a stacked group, a convex face resting on another face (any convex pair but two
	/// boxes, and convex bodies on a btStaticPlaneShape) gets the points of its whole patch, found
	/// from the shapes' support functions, where Bullet's GJK/EPA reported one or two of them (it
	/// finds one new point per step; a column of 10 cylinders pivoted on them). The reach is D30's
	/// (m_diagnostics.m_boxFaceReachPerFall). Groups without stacks keep Bullet's points
	/// (docs/design.md, D33).
	bool m_completeContactPatches = true;

	/// Ablation switches and tolerances (see btShockPropagationDiagnostics); leave as they are
	/// unless reproducing docs/design.md.
	btShockPropagationDiagnostics m_diagnostics;
};

#endif  // BT_SHOCK_PROPAGATION_SETTINGS_H
