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
	int m_numSkippedBodies = 0;   ///< bodies left out because of NaN/Inf state (docs/design.md, section 10)
	int m_numGlobalSweeps = 0;    ///< corrector sweeps (Bullet's own, every body free; they end once converged)
	int m_numLayerSweeps = 0;     ///< predictor sweeps: per cycle, the most any layer visit ran
	int m_numBoxFaceCorners = 0;  ///< contact points added where a box face rested on a box (D30)
	int m_numPatchPoints = 0;     ///< contact points added to other convex patches (D33)
	int m_numSkippedManifolds = 0;///< manifolds left out (non-finite points, or touching skipped bodies)

	// Wall-clock time per phase (milliseconds).
	double m_timeGraphMs = 0;            ///< contact graph and stack layers
	double m_timeSetupMs = 0;            ///< Bullet's row setup (once per step), rows into layers
	double m_timeGlobalDynamicsMs = 0;   ///< corrector sweeps (and Bullet's own solve of groups without stacks)
	double m_timeLayersMs = 0;           ///< predictor (shock propagation: up and down passes, cycles)
	double m_timeCollisionMs = 0;        ///< always 0: the second correction runs no narrowphase (D4)
	double m_timeCorrectionMs = 0;       ///< finish, position correction at CD(t) and the second correction
};

#endif  // BT_SHOCK_PROPAGATION_STATISTICS_H
