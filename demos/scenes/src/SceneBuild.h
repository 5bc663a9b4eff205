// Private helpers shared by the scene families: placement constants, the ground, parameter checks.
// Not installed; scene code only.

#ifndef SCENES_SCENE_BUILD_H
#define SCENES_SCENE_BUILD_H

#include "scenes/Scene.h"

#include <cstdint>
#include <string>

namespace scenes
{
namespace build
{
/// How far a resting body sinks into what it rests on (m). Exactly touching boxes may get no contact at
/// all in float (the faces end up a few ulp apart), so every resting contact starts 10 micrometres deep
/// and exists at step 1. Far below any solver's penetration slop.
constexpr double kRestOverlap = 1e-5;

/// Gap between side-by-side neighbours (m), so they never start interpenetrating sideways.
constexpr double kSideGap = 1e-3;

/// Half thickness of the ground slab (m); its top face is at y = 0.
constexpr double kGroundHalfThickness = 0.5;

/// Smallest half width of the ground slab (m); scenes with a larger footprint ask for more.
constexpr double kMinGroundHalfWidth = 50.0;

/// Largest count any parameter may ask for, a guard against typos such as n=1e9.
constexpr int kMaxCount = 1000000;

/// Description of the "mu" parameter most scenes have.
constexpr const char* kMuDescription = "combined friction coefficient of every contact";

/// The standard box of the project's measurements: 1 x 0.5 x 1 m (width x height x depth).
inline btVector3 standardBoxHalfExtents() { return btVector3(btScalar(0.5), btScalar(0.25), btScalar(0.5)); }

/// Adds the static ground slab (top face at y = 0, half width max(kMinGroundHalfWidth,
/// footprintHalfWidth)) with combined friction `mu`, names it "ground" and returns it.
btRigidBody* addGround(SceneContent& content, btScalar footprintHalfWidth, btScalar mu);

/// Shape kinds of the shape grid (src/ShapeKinds.cpp says what each is): a scene's "shape" parameter.
enum ShapeKind
{
	kBox = 0,
	kHull = 1,
	kHullFeatures = 2,
	kHexPrism = 3,
	kCylinder = 4,
	kCompound = 5,
	kCapsule = 6,
	kSphere = 7,
};
/// Ground kinds of the shape grid: a scene's "ground" parameter.
enum GroundKind
{
	kBoxGround = 0,
	kPlaneGround = 1,
	kMeshGround = 2,
	kMeshEdgesGround = 3,
	kHeightfieldGround = 4,
};
const char* shapeKindNames();
const char* groundKindNames();

/// A body shape of `kind` fitting the half extents `half` (owned by `content`); throws
/// std::invalid_argument on an unknown kind.
btCollisionShape* addShapeOf(SceneContent& content, int kind, const btVector3& half);

/// The static ground of `kind` with its top surface at y = 0, at least `footprintHalfWidth` wide
/// (half width), combined friction `mu`, named "ground"; kind 0 is addGround().
btRigidBody* addGroundOf(SceneContent& content, int kind, btScalar footprintHalfWidth, btScalar mu);

inline btScalar degreesToRadians(btScalar degrees) { return degrees * SIMD_PI / btScalar(180); }

/// Pure translation.
btTransform at(btScalar x, btScalar y, btScalar z);

/// Rotation by `angleRad` about `axis` (unit), then translation to `origin`.
btTransform rotatedAt(const btVector3& axis, btScalar angleRad, const btVector3& origin);

/// Centre height of the body at `level` (0 = lowest) of a column of equal bodies of half height
/// `halfHeight` standing on a support whose top is at `baseY`; each one sinks `overlap` into the one below.
btScalar columnCentreY(btScalar baseY, btScalar halfHeight, int level, btScalar overlap = btScalar(kRestOverlap));

/// Integer parameter >= minimum (and <= kMaxCount); throws std::invalid_argument otherwise.
int countParam(const Params& params, const std::string& name, int minimum);
/// Parameter that must be > 0; throws std::invalid_argument otherwise.
btScalar positiveParam(const Params& params, const std::string& name);
/// Parameter that must be >= 0; throws std::invalid_argument otherwise.
btScalar nonNegativeParam(const Params& params, const std::string& name);
/// The "seed" parameter of a seeded scene: a whole number in [0, 2^32); throws std::invalid_argument otherwise.
std::uint32_t seedParam(const Params& params);
/// Four static walls (0.2 m thick, `halfHeight` high from the ground) whose inner faces bound the
/// square pit |x|, |z| <= width / 2, friction `mu`; they close its corners.
void addSquarePit(SceneContent& content, btScalar width, btScalar halfHeight, btScalar mu);
/// Throws std::invalid_argument(what) unless `ok` (createScene() prefixes the scene name).
void require(bool ok, const std::string& what);

/// Records the facts every scene has: "expectStanding" and "bodies" (number of dynamic bodies).
void finishScene(SceneContent& content, bool expectStanding);

}  // namespace build
}  // namespace scenes

#endif  // SCENES_SCENE_BUILD_H
