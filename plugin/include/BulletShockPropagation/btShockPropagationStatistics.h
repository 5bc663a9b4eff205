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

#ifndef BT_SHOCK_PROPAGATION_STATISTICS_H
#define BT_SHOCK_PROPAGATION_STATISTICS_H

/// What the solver did in the last simulation step (summed over all solveGroup calls of the step).
struct btShockPropagationStatistics
{
	int m_numGroups = 0;          ///< solveGroup calls (Bullet batches small islands into one)
	int m_numComponents = 0;      ///< connected components of the contact graphs
	int m_numLayers = 0;          ///< largest K (stack layers) of any group
	int m_largestLayer = 0;       ///< most free bodies in one layer
	int m_numFixatedBodies = 0;   ///< body fixations over all layers (a body is fixated at most once)
	int m_numLayeredGroups = 0;   ///< groups solved layer by layer (the others had no stacks)
	int m_numSkippedBodies = 0;   ///< bodies left out because of NaN/Inf state (docs/design.md, section 12)
	int m_numGlobalSweeps = 0;    ///< PGS sweeps of the global pass (D21: it ends once converged)
	int m_numLayerSweeps = 0;     ///< PGS sweeps of the layer passes, over all layers (D19: they end once converged)
	int m_numWeightSweeps = 0;    ///< PGS sweeps of the weight pass, over all its layers (D13)
	int m_numWeightRejections = 0;///< weight-pass layers that could not carry their load (D13 guard)
	int m_numSlidingComposites = 0;///< sliding bases that carried what rests on them (D23)
	int m_numSharedFactorTransfers = 0;///< load transfers solved with their support block's factor (D24)
	int m_numTippingComposites = 0;///< bodies that tipped (D25) or slid (D29) with what rests on them as one rigid body
	int m_numRigidSlidingComposites = 0;///< of those, bodies that slid with what rests on them (D29)
	int m_numBoxFaceCorners = 0;  ///< contact points added where a box face rested on a box (D30)
	int m_numSkippedManifolds = 0;///< manifolds left out (non-finite points, or touching skipped bodies)

	// Wall-clock time per phase (milliseconds).
	double m_timeGraphMs = 0;            ///< contact graph and stack layers
	double m_timeSetupMs = 0;            ///< Bullet's row setup (once per step), rows into layers, the warm-start split (D5)
	double m_timeGlobalDynamicsMs = 0;   ///< global pass (and Bullet's own solve of groups without stacks)
	double m_timeLayersMs = 0;           ///< layer passes, bottom-up
	double m_timeWeightFeelingMs = 0;    ///< top-down pass of the weight-feeling mode (D13)
	double m_timeCollisionMs = 0;        ///< always 0: the second correction runs no narrowphase (D4)
	double m_timeCorrectionMs = 0;       ///< finish, position correction at CD(t) and the second correction
};

#endif  // BT_SHOCK_PROPAGATION_STATISTICS_H
