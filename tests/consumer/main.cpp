// Built against the install tree by the InstallConsumer test: the README's swap-in lines.
#include <BulletShockPropagation/btShockPropagationCommon.h>
#include <btBulletDynamicsCommon.h>

#include <cstdio>

int main()
{
	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher(&configuration);
	btDbvtBroadphase broadphase;
	btShockPropagationDynamicsWorld world(&dispatcher, &broadphase, nullptr, &configuration);
	world.setGravity(btVector3(0, btScalar(-9.81), 0));

	btBoxShape groundShape(btVector3(10, 1, 10));
	btRigidBody ground(0, nullptr, &groundShape);
	ground.getWorldTransform().setOrigin(btVector3(0, -1, 0));
	world.addRigidBody(&ground);

	btBoxShape boxShape(btVector3(btScalar(0.5), btScalar(0.25), btScalar(0.5)));
	btVector3 inertia;
	boxShape.calculateLocalInertia(1, inertia);
	btRigidBody lower(1, nullptr, &boxShape, inertia), upper(1, nullptr, &boxShape, inertia);
	lower.getWorldTransform().setOrigin(btVector3(0, btScalar(0.24999), 0));
	upper.getWorldTransform().setOrigin(btVector3(0, btScalar(0.74998), 0));
	for (btRigidBody* b : {&lower, &upper})
	{
		b->setActivationState(DISABLE_DEACTIVATION);
		world.addRigidBody(b);
	}
	for (int i = 0; i < 120; ++i) world.stepSimulation(btScalar(1.0 / 60.0), 1, btScalar(1.0 / 60.0));
	const btScalar y = upper.getCenterOfMassPosition().y();
	std::printf("upper box y after 2 s: %.5f m (start 0.74998), layers %d\n", double(y), world.getShockPropagationSolver()->getStatistics().m_numLayers);
	for (btRigidBody* b : {&upper, &lower, &ground}) world.removeRigidBody(b);
	return (y > btScalar(0.74) && y < btScalar(0.76)) ? 0 : 1;
}
