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

#ifndef BT_SHOCK_PROPAGATION_COMMON_H
#define BT_SHOCK_PROPAGATION_COMMON_H

/// Umbrella header of BulletShockPropagation, like Bullet's btBulletDynamicsCommon.h.
///
/// Solver-only drop-in, on any btDiscreteDynamicsWorld (layered solve and in-layer correction):
///     world->setConstraintSolver(new btShockPropagationConstraintSolver);
/// Full algorithm (adds collision detection at t + dt and the global correction):
///     btShockPropagationDynamicsWorld world(dispatcher, broadphase, nullptr, configuration);

#include "btContactGraph.h"
#include "btShockPropagationConstraintSolver.h"
#include "btShockPropagationDynamicsWorld.h"
#include "btShockPropagationSettings.h"
#include "btShockPropagationStatistics.h"
#include "btStackLayers.h"

#endif  // BT_SHOCK_PROPAGATION_COMMON_H
