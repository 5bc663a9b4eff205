#include "viewer/BodyColours.h"

#include <BulletShockPropagation/btShockPropagationConstraintSolver.h>

#include <algorithm>

namespace viewer
{
namespace
{
// Neighbouring heights differ in hue, so bands of a tower or a wall alternate visibly.
const Rgb kLayerPalette[kLayerPaletteSize] = {
	{0.85f, 0.25f, 0.20f},  // red
	{0.95f, 0.65f, 0.15f},  // orange
	{0.30f, 0.70f, 0.30f},  // green
	{0.20f, 0.55f, 0.85f},  // blue
	{0.60f, 0.35f, 0.80f},  // violet
	{0.90f, 0.85f, 0.25f},  // yellow
	{0.20f, 0.75f, 0.75f},  // teal
	{0.85f, 0.40f, 0.60f},  // pink
};
}  // namespace

Rgb layerColour(int height)
{
	if (height < 1) return layerlessColour();
	return kLayerPalette[(height - 1) % kLayerPaletteSize];
}

Rgb layerlessColour() { return {0.78f, 0.62f, 0.45f}; }  // sandstone

Rgb staticColour() { return {0.55f, 0.55f, 0.58f}; }

Rgb driftColour(double driftMetres)
{
	const Rgb rest = layerlessColour(), moved = {0.85f, 0.12f, 0.10f};
	const float t = float(std::min(1.0, std::max(0.0, driftMetres / harness::kStandingDriftMeters)));
	return {rest.r + (moved.r - rest.r) * t, rest.g + (moved.g - rest.g) * t, rest.b + (moved.b - rest.b) * t};
}

std::unordered_map<const btCollisionObject*, Rgb> bodyColours(harness::Trial& trial, ColourMode mode)
{
	std::unordered_map<const btCollisionObject*, Rgb> colours;
	if (mode == ColourMode::Drift)
	{
		for (const btRigidBody* body : trial.bodies()) colours[body] = driftColour(trial.drift().drift(body));
		return colours;
	}
	const btShockPropagationConstraintSolver* solver = trial.simulation().shockSolver();
	if (mode != ColourMode::StackLayer || !solver) return colours;
	for (int i = 0; i < solver->getNumLayeredBodies(); ++i)
		colours[solver->getLayeredBody(i)] = layerColour(solver->getLayeredBodyHeight(i));
	return colours;
}
}  // namespace viewer
