#include "viewer/Comparison.h"

#include <stdexcept>

namespace viewer
{
Comparison::Comparison(const ComparisonSetup& setup) : m_setup(setup)
{
	if (m_setup.solvers.empty()) throw std::invalid_argument("no solver to show");
	reset();
}

void Comparison::reset()
{
	m_trials.clear();
	m_shots = 0;
	for (const harness::SolverSpec& spec : m_setup.solvers)
		m_trials.emplace_back(new harness::Trial(spec, m_setup.scene, m_setup.params, m_setup.timeStep));
}

void Comparison::step()
{
	for (auto& t : m_trials) t->step();
}

void Comparison::stepTo(int steps)
{
	while (this->steps() < steps) step();
}

int Comparison::steps() const { return m_trials.front()->steps(); }

double Comparison::time() const { return m_trials.front()->simulation().time(); }

void Comparison::shootBox(const btVector3& origin, const btVector3& direction, double speed, double edge, double mass)
{
	const btScalar half = btScalar(edge / 2);
	const btVector3 velocity = direction.normalized() * btScalar(speed);
	for (auto& t : m_trials)
	{
		scenes::SceneContent& scene = t->scene();
		const btRigidBody* ground = scene.ground();
		// The scene's combined mu: the ground has sqrt(mu), so the box gets the same.
		const double mu = ground ? double(ground->getFriction()) * double(ground->getFriction()) : 0.5;
		btRigidBody* box = scene.addBody(new btBoxShape(btVector3(half, half, half)), btScalar(mass),
										 btTransform(btQuaternion::getIdentity(), origin), btScalar(mu));
		box->setLinearVelocity(velocity);
	}
	++m_shots;
}
}  // namespace viewer
