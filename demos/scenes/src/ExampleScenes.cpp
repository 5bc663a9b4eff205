// Bullet's own example programs as registry scenes, written from their published sizes and
// settings (the construction is this project's): basic_demo_block (BasicDemo's 5 x 5 x 5 block of
// cubes dropped on the ground).

#include "SceneBuild.h"
#include "SceneCatalog.h"

namespace scenes
{
// ---------------------------------------------------------------------------------------------------
// basic_demo_block: BasicDemo (examples/BasicDemo) drops a 5 x 5 x 5 block of cubes of edge 0.2 m and
// 1 kg, side by side with no gap, its lowest layer's centres 2 m above a static box ground (Bullet's
// default friction 0.5 per body: 0.25 combined; no restitution; 10 iterations at 60 Hz). Physics: the
// block falls as one body (its cubes touch at zero distance and fall together), lands flat and stays
// a block: every cube ends where it started in x and z, and the layers rest on each other
// (centres 0.1 + 0.2 k m above the ground).

Params basicDemoBlockParams()
{
	return {
		{"n", 5, "-", "cubes along each edge of the block (BasicDemo: 5)"},
		{"size", 0.2, "m", "cube edge (BasicDemo: 0.2)"},
		{"height", 2, "m", "height of the lowest layer's centres at the start (BasicDemo: 2)"},
		{"mass", 1, "kg", "mass of each cube (BasicDemo: 1)"},
		{"mu", 0.25, "-", "combined friction coefficient of every contact (Bullet's default 0.5 per body: 0.25)"},
	};
}

std::unique_ptr<SceneContent> createBasicDemoBlock(btDiscreteDynamicsWorld& world, const Params& params)
{
	const int n = build::countParam(params, "n", 1);
	const btScalar size = build::positiveParam(params, "size");
	const btScalar height = build::positiveParam(params, "height");
	const btScalar mass = build::positiveParam(params, "mass");
	const btScalar mu = build::nonNegativeParam(params, "mu");
	const btScalar half = size / 2;
	build::require(height >= half, "height must leave the lowest layer above the ground");

	auto content = std::make_unique<SceneContent>(world);
	build::addGround(*content, size * btScalar(n), mu);
	btCollisionShape* shape = content->addShape(new btBoxShape(btVector3(half, half, half)));
	for (int k = 0; k < n; ++k)
		for (int i = 0; i < n; ++i)
			for (int j = 0; j < n; ++j)
			{
				btRigidBody* cube = content->addBody(shape, mass, build::at(size * btScalar(i), height + size * btScalar(k), size * btScalar(j)), mu);
				if (k == n - 1 && i == 0 && j == 0) content->name("top", cube);
			}
	content->facts["drop"] = double(height - half);  // m the block falls before it lands
	content->facts["cubeSize"] = double(size);
	build::finishScene(*content, height == half);
	return content;
}

}  // namespace scenes
