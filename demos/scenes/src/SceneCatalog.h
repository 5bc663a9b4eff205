// Private list of every scene's create function and parameter list, grouped by the file that defines
// them. src/Registry.cpp turns them into the public table; nothing else should need this header.

#ifndef SCENES_SCENE_CATALOG_H
#define SCENES_SCENE_CATALOG_H

#include "scenes/Scene.h"

#include <memory>

namespace scenes
{
// StackScenes.cpp
std::unique_ptr<SceneContent> createSingleBox(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createSlidingBox(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createFreeFall(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createTower(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createMassRatioTower(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createLargeOnSmall(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createLeaningTower(btDiscreteDynamicsWorld& world, const Params& params);
Params singleBoxParams();
Params slidingBoxParams();
Params freeFallParams();
Params towerParams();
Params massRatioTowerParams();
Params largeOnSmallParams();
Params leaningTowerParams();

// PyramidScenes.cpp
std::unique_ptr<SceneContent> createSparseStacking(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createDenseRandom(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createPyramid(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createOverlapRecovery(btDiscreteDynamicsWorld& world, const Params& params);
Params sparseStackingParams();
Params denseRandomParams();
Params pyramidParams();
Params overlapRecoveryParams();

// MasonryScenes.cpp
std::unique_ptr<SceneContent> createWall(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createRoundTower(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createDoor(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createArch(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createCardHouse(btDiscreteDynamicsWorld& world, const Params& params);
Params wallParams();
Params roundTowerParams();
Params doorParams();
Params archParams();
Params cardHouseParams();

// MechanismScenes.cpp
std::unique_ptr<SceneContent> createSeesaw(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createLoadedPlank(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createFrictionRamp(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createDominoRow(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createHingeBridge(btDiscreteDynamicsWorld& world, const Params& params);
Params seesawParams();
Params loadedPlankParams();
Params frictionRampParams();
Params dominoRowParams();
Params hingeBridgeParams();

// TruthScenes.cpp
std::unique_ptr<SceneContent> createHarmonicStack(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createPushedStack(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createRampStack(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createLedgeColumn(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createLoadedLintel(btDiscreteDynamicsWorld& world, const Params& params);
Params harmonicStackParams();
Params pushedStackParams();
Params rampStackParams();
Params ledgeColumnParams();
Params loadedLintelParams();

// BenchmarkScenes.cpp
std::unique_ptr<SceneContent> createLeaningColumns(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createRagdollPile(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createHeavyTopColumn(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createBoxes3000(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createStack1000(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createFlatBoxes(btDiscreteDynamicsWorld& world, const Params& params);
Params leaningColumnsParams();
Params ragdollPileParams();
Params heavyTopColumnParams();
Params boxes3000Params();
Params stack1000Params();
Params flatBoxesParams();

// ShapeScenes.cpp
std::unique_ptr<SceneContent> createShapeColumn(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createRoundOnBlock(btDiscreteDynamicsWorld& world, const Params& params);
Params shapeColumnParams();
Params roundOnBlockParams();
std::unique_ptr<SceneContent> createLeaningPlank(btDiscreteDynamicsWorld& world, const Params& params);
Params leaningPlankParams();

// StructureScenes.cpp
std::unique_ptr<SceneContent> createTableStack(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createPlankCrib(btDiscreteDynamicsWorld& world, const Params& params);
std::unique_ptr<SceneContent> createHullBin(btDiscreteDynamicsWorld& world, const Params& params);
Params tableStackParams();
Params plankCribParams();
Params hullBinParams();

// ExampleScenes.cpp
std::unique_ptr<SceneContent> createBasicDemoBlock(btDiscreteDynamicsWorld& world, const Params& params);
Params basicDemoBlockParams();

}  // namespace scenes

#endif  // SCENES_SCENE_CATALOG_H
