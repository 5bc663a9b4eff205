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

/// What a fixated (infinite-mass) body looks like to the layer above it (decision D1).
/// Measured (README, "Fixation mode"): on a 200-brick wall, full kept velocity lets the
/// small angular velocity PGS leaves in each layer grow from layer to layer (an upper body
/// resting on a slightly rotating support is pushed up by the rising side and never pulled by
/// the sinking side), so the default keeps the linear velocity only.
enum btShockPropagationFixationMode
{
	/// Infinite mass, linear and angular velocity kept: upper bodies come to rest relative to the
	/// lower one's full rigid motion.
	BT_FIXATION_KEEP_VELOCITY = 0,
	/// Infinite mass and zero velocity, as in Erleben's OpenTissue code (set_fixed).
	BT_FIXATION_ZERO_VELOCITY = 1,
	/// Infinite mass, linear velocity kept, angular velocity treated as zero: a stack on a sliding
	/// or carried support still moves with it, and rotation noise does not climb the stack. Default.
	BT_FIXATION_KEEP_LINEAR_VELOCITY = 2
};

/// Every tunable of the plugin, with its default, unit and reason. Defaults are set here only.
/// Bullet's own btContactSolverInfo still supplies friction/restitution thresholds, warm-starting
/// factor, SOR and joint ERP; its m_numIterations, m_erp2 and split-impulse fields are replaced by
/// the fields below while the plugin solves.
struct btShockPropagationSettings
{
	/// Weighting value f in [0, 1] (unitless): the fraction of the time step integrated by the
	/// global pass with every body free, dynamics(f dt); the layered pass integrates (1 - f) dt.
	/// Larger f passes more weight down the stack ("weight feeling"); the corrections keep the
	/// unconverged global solve from sagging. Measured (README): 0.5 holds the 200-brick wall with
	/// overhanging end bricks (they need the weight of the rows above); 0.1 and 0.25 lose it (D2).
	/// f = 0 skips the global pass (OpenTissue would run an impulse-only pass there).
	btScalar m_weighting = btScalar(0.5);

	/// PGS sweeps of the global pass dynamics(f dt) (count). 10 as in OpenTissue (D7).
	int m_globalIterations = 10;
	/// PGS sweeps of each layer's dynamics((1 - f) dt) (count). A layer is a short problem
	/// (one contact deep), so 10 sweeps converge it where a whole stack would need O(n^2) (D7).
	int m_layerIterations = 10;
	/// PGS sweeps of each position correction, per layer and in the second correction (count).
	int m_correctionIterations = 10;

	/// Run collision detection again at t + dt and a global position correction with every
	/// body free ("anti-rippling", the paper's fix for ripples; needs btShockPropagationDynamicsWorld).
	bool m_secondCorrection = true;

	/// Solve the second correction layer by layer (bottom-up, lower bodies fixated) on the contact
	/// graph of CD(t + dt), instead of as one global mass-weighted projection with every body free.
	/// The global form is the paper's; with 10 sweeps it does not converge on mass ratios (a
	/// 1000:1 tower is squeezed apart), so the layered form is the default (measured, README).
	bool m_layeredSecondCorrection = true;

	/// See btShockPropagationFixationMode (D1).
	btShockPropagationFixationMode m_fixationMode = BT_FIXATION_KEEP_LINEAR_VELOCITY;

	/// D14 (beyond the paper): a fixated body that moves into a free one above it pushes it at most
	/// at the common velocity of an inelastic collision of the two (row effective masses), not at
	/// its own speed. A support heavier than its load is unaffected; a light body thrown into a
	/// heavy one (by a joint pulling it, say) no longer throws the heavy one at its own speed, which
	/// gave hostile worlds 5x the kinetic energy they started with (README, "Behaviour on bad input").
	bool m_inelasticFixation = true;

	/// A manifold is a contact-graph edge if one of its points is at most this far apart
	/// (metres; negative = penetrating). 0.02 m is Bullet's default contact breaking threshold,
	/// i.e. every point Bullet keeps counts (D8). Manifolds farther apart are solved in the
	/// global pass and corrections only.
	btScalar m_graphContactThreshold = btScalar(0.02);

	/// Fraction (unitless, 0..1] of each measured penetration removed by a correction. 1 removes
	/// all of it, as OpenTissue's correction() does (erp = 1).
	btScalar m_correctionFraction = btScalar(1);

	/// Penetration left in place by corrections (metres). 0 is OpenTissue's choice; in Bullet it
	/// leaves resting boxes at zero distance, where the box-box test may report no contact, so the
	/// next step sees a gap and the body falls into it again. 0.5 mm keeps resting contacts alive
	/// (measured, README "Choices measured": tower of 40 0.16 -> 0.00 cm, round tower 0.74 -> 0.04 cm).
	btScalar m_correctionSlop = btScalar(0.0005);

	/// Two friction rows per contact point (a four-sided friction pyramid) instead of Bullet's
	/// default one velocity-aligned row. Bullet's single row lets towers creep sideways
	/// (bullet-notes.md); a layer is small, so the second row is cheap.
	bool m_twoFrictionDirections = true;

	/// Layered solve also when the contact graph has a single layer (no stacks). Off: such groups
	/// get one ordinary solve of the full step (no f split), so scenes without stacks cost what
	/// stock Bullet costs.
	bool m_layerFlatGroups = false;

	/// Order the stack layers by support as well as by BFS distance (btStackLayers): a body that
	/// rests on another (mean contact normal within m_supportAngle of the up direction, up =
	/// -gravity) is put above it. Off: Erleben's plain BFS layers, which clamp the top box of the
	/// taller column of a door between two fixated bodies (algorithm.md 2.4 and 2.5).
	bool m_supportOrdering = true;

	/// Corrections also remove the velocity into every contact that penetrates (D11, inelastic,
	/// normal direction only). Without it a body the correction has pushed out to zero distance
	/// can lose its contact (Bullet's box-box test reports none at zero distance) and gain g dt
	/// of velocity into the ground every step while the correction keeps moving it back.
	bool m_correctionStopsApproach = true;

	/// Approach speed (m/s) above which a penetrating contact counts as missed by the dynamics
	/// phase and gets its approach velocity removed (m_correctionStopsApproach). Resting contacts
	/// approach far slower; projecting them too (normal rows without friction) would spin the
	/// bodies of a stack. 0.25 m/s is 1.5 g dt at 60 Hz.
	btScalar m_correctionApproachSpeed = btScalar(0.25);

	/// Largest angle (radians) between a contact normal and the up direction for which the
	/// contact counts as support; steeper contacts are side contacts. 1.0472 = 60 degrees.
	btScalar m_supportAngle = btScalar(1.0471975511965976);

	/// Weight feeling (D13, beyond the paper; in the spirit of Xiong et al., "Two-Pass Shock
	/// Propagation", SCA 2025): after the bottom-up layer pass, a top-down pass hands each layer's
	/// reaction impulses, which fixation withheld from the bodies below, to those bodies and
	/// re-solves their layer, so the ground carries the whole stack and loads tip what they rest on.
	bool m_weightFeeling = false;

	/// PGS sweeps of each layer's re-solve in the weight pass (count). The load handed down has
	/// to be carried within the step: at 10 sweeps a 20-row pyramid and the wall fall, at 20 the
	/// wall still loses its weight feeling, 40 hold both (README, D13).
	int m_weightIterations = 40;
};

#endif  // BT_SHOCK_PROPAGATION_SETTINGS_H
