// Built against an install tree by the consumer tests (tests/consumer/RunConsumer.cmake), with
// CMake (CMakeLists.txt) or a plain Makefile (pkg-config): the README's swap-in lines on a tower of
// five boxes. Usage: consumer float|double. Fails unless btScalar has the expected precision, the
// plugin's layered solve ran, and after 2 s the top box is within 1 mm of its start sideways and
// of where it was at 0.5 s, and has sunk less than 0.5 mm per contact below it (the resting
// penetration the plugin leaves, m_correctionSlop: 0.49 mm at 60 Hz). Stock Bullet's solver
// fails it (the top box slides 2.4 mm).
#include <BulletShockPropagation/btShockPropagationCommon.h>
#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <cstdio>
#include <cstring>

int main(int argc, char** argv)
{
	const bool wantDouble = argc > 1 && std::strcmp(argv[1], "double") == 0;
	if (argc < 2 || (!wantDouble && std::strcmp(argv[1], "float") != 0))
	{
		std::fprintf(stderr, "usage: consumer float|double\n");
		return 2;
	}
	if (sizeof(btScalar) != (wantDouble ? sizeof(double) : sizeof(float)))
	{
		std::fprintf(stderr, "btScalar has %d bytes, expected %s\n", int(sizeof(btScalar)), argv[1]);
		return 1;
	}

	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher(&configuration);
	btDbvtBroadphase broadphase;
	btShockPropagationDynamicsWorld world(&dispatcher, &broadphase, nullptr, &configuration);
	world.setGravity(btVector3(0, btScalar(-9.81), 0));

	btBoxShape groundShape(btVector3(10, 1, 10));
	btRigidBody ground(0, nullptr, &groundShape);
	ground.getWorldTransform().setOrigin(btVector3(0, -1, 0));
	world.addRigidBody(&ground);

	// Five 1 x 0.5 x 1 m boxes of 1 kg, each resting on the one below (10 um gaps).
	const int numBoxes = 5;
	btBoxShape boxShape(btVector3(btScalar(0.5), btScalar(0.25), btScalar(0.5)));
	btVector3 inertia;
	boxShape.calculateLocalInertia(1, inertia);
	btRigidBody* boxes[numBoxes];
	for (int i = 0; i < numBoxes; ++i)
	{
		boxes[i] = new btRigidBody(1, nullptr, &boxShape, inertia);
		boxes[i]->getWorldTransform().setOrigin(btVector3(0, btScalar(0.25 + i * 0.50001), 0));
		boxes[i]->setActivationState(DISABLE_DEACTIVATION);
		world.addRigidBody(boxes[i]);
	}
	const btRigidBody& top = *boxes[numBoxes - 1];
	const btVector3 start = top.getCenterOfMassPosition();
	btVector3 settled = start;

	int layers = 0;
	for (int i = 1; i <= 120; ++i)
	{
		world.stepSimulation(btScalar(1.0 / 60.0), 1, btScalar(1.0 / 60.0));
		const int stepLayers = world.getShockPropagationSolver()->getStatistics().m_numLayers;
		if (stepLayers > layers) layers = stepLayers;
		if (i == 30) settled = top.getCenterOfMassPosition();
	}
	const btVector3 end = top.getCenterOfMassPosition();
	const double sideways = double(btVector3(end.x() - start.x(), 0, end.z() - start.z()).length());
	const double sunk = double(start.y() - end.y());
	const double creep = double((end - settled).length());
	std::printf("%s: top box of %d after 2 s: sideways %.6f m (< 0.001), sunk %.6f m (< 0.0025), "
				"moved since 0.5 s %.6f m (< 0.001); up to %d layers\n",
				argv[1], numBoxes, sideways, sunk, creep, layers);
	const bool stands = sideways < 0.001 && sunk > -0.001 && sunk < 0.0005 * numBoxes && creep < 0.001;

	for (int i = 0; i < numBoxes; ++i)
	{
		world.removeRigidBody(boxes[i]);
		delete boxes[i];
	}
	world.removeRigidBody(&ground);
	if (layers < numBoxes)
	{
		std::fprintf(stderr, "the plugin's layered solve did not run (%d layers)\n", layers);
		return 1;
	}
	return stands ? 0 : 1;  // false for NaN too
}
