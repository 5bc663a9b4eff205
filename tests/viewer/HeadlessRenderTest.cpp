// Viewer specs, rendered headless (EGL, no display): what a person would check by looking. The
// picture is not blank, two viewports differ exactly where their physics differs, and layer
// colouring paints a known body in its layer's colour. Without an offscreen OpenGL context every
// test here fails with the reason; none is skipped.
#include <viewer/BodyColours.h>
#include <viewer/Comparison.h>
#include <viewer/Labels.h>
#include <viewer/Offscreen.h>
#include <viewer/Pictures.h>
#include <viewer/Renderer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <set>
#include <string>

namespace
{
using viewer::Image;
using viewer::Rgb;

constexpr double kTimeStepSeconds = 1.0 / 60.0;
/// Two chromaticities (r, g, b over their sum) match within this.
constexpr double kHueTolerance = 0.025;

harness::SolverSpec solver(harness::SolverKind kind, int iterations = 10)
{
	harness::SolverSpec s;
	s.kind = kind;
	s.iterations = iterations;
	return s;
}

/// Same hue as `colour`, whatever the shading (the renderer's light is white).
bool hasHue(const unsigned char* p, const Rgb& colour)
{
	const double sum = double(p[0]) + p[1] + p[2];
	const double expected = double(colour.r) + colour.g + colour.b;
	if (sum < 60) return false;  // too dark to tell
	return std::fabs(p[0] / sum - colour.r / expected) < kHueTolerance && std::fabs(p[1] / sum - colour.g / expected) < kHueTolerance &&
		   std::fabs(p[2] / sum - colour.b / expected) < kHueTolerance;
}

/// Fraction of pixels (over the whole image) for which `match` holds.
template <class F>
double fraction(const Image& image, F match)
{
	long count = 0;
	for (int y = 0; y < image.height; ++y)
		for (int x = 0; x < image.width; ++x) count += match(image.pixel(x, y)) ? 1 : 0;
	return double(count) / (double(image.width) * image.height);
}

class Headless : public ::testing::Test
{
protected:
	static void SetUpTestSuite()
	{
		s_context = viewer::OffscreenContext::create(s_error);
		if (s_context) s_renderer.reset(new viewer::Renderer());
	}
	static void TearDownTestSuite()
	{
		s_renderer.reset();
		s_context.reset();
	}
	void SetUp() override
	{
		ASSERT_TRUE(s_context) << "headless OpenGL is not available, so the viewer cannot be tested: " << s_error;
	}

	/// One trial drawn alone into a width x height picture.
	static Image draw(harness::Trial& trial, const viewer::OrbitCamera& camera, viewer::ColourMode colours, int width = 200, int height = 240)
	{
		viewer::Framebuffer framebuffer(width, height);
		framebuffer.bind();
		viewer::Viewport viewport;
		viewport.width = width;
		viewport.height = height;
		viewer::DrawOptions options;
		options.colours = colours;
		s_renderer->drawTrial(trial, camera, viewport, options);
		return framebuffer.read();
	}

	static std::unique_ptr<viewer::OffscreenContext> s_context;
	static std::unique_ptr<viewer::Renderer> s_renderer;
	static std::string s_error;
};
std::unique_ptr<viewer::OffscreenContext> Headless::s_context;
std::unique_ptr<viewer::Renderer> Headless::s_renderer;
std::string Headless::s_error;

TEST_F(Headless, SmallTowerPictureShowsSkyGroundAndShadedBoxes)
{
	viewer::Comparison comparison({"tower", {{"n", 3}}, {solver(harness::SolverKind::ShockWorld)}, kTimeStepSeconds});
	viewer::StripOptions options;
	options.checkpoints = {1};
	options.cellWidth = 200;
	options.cellHeight = 160;
	viewer::OffscreenText text;
	const Image image = viewer::renderStrip(comparison, options, *s_renderer, text);
	ASSERT_EQ(image.width, 200);
	ASSERT_GT(image.height, 160);  // the label band on top

	const Rgb sky = viewer::backgroundColour(), ground = viewer::groundColour(), box = viewer::layerlessColour();
	EXPECT_GT(fraction(image, [&](const unsigned char* p) { return hasHue(p, sky); }), 0.05) << "no sky";
	EXPECT_GT(fraction(image, [&](const unsigned char* p) { return hasHue(p, ground); }), 0.2) << "no ground";
	EXPECT_GT(fraction(image, [&](const unsigned char* p) { return hasHue(p, box); }), 0.02) << "no boxes";
	// Shaded: the boxes' pixels come in several brightnesses (faces lit differently).
	std::set<int> brightness;
	for (int y = 0; y < image.height; ++y)
		for (int x = 0; x < image.width; ++x)
			if (hasHue(image.pixel(x, y), box)) brightness.insert((image.pixel(x, y)[0] + image.pixel(x, y)[1] + image.pixel(x, y)[2]) / 24);
	EXPECT_GE(brightness.size(), 3u) << "boxes look flat";
	// The label: dark text pixels in the band above the viewport.
	EXPECT_GT(fraction(image, [](const unsigned char* p) { return p[0] + p[1] + p[2] < 150; }), 0.002) << "no label text";
}

TEST_F(Headless, ViewportsDifferWhereThePhysicsDiffersAndOnlyThere)
{
	// A 20-box tower after 4 s: stock SI at 10 iterations has let it fall, the plugin holds it.
	viewer::Comparison comparison({"tower", {{"n", 20}},
								   {solver(harness::SolverKind::StockSI), solver(harness::SolverKind::StockSI), solver(harness::SolverKind::ShockWorld)},
								   kTimeStepSeconds});
	const viewer::OrbitCamera camera = viewer::pictureCamera(comparison, viewer::StripOptions(), 200.0 / 240.0);
	comparison.stepTo(int(4.0 / kTimeStepSeconds));
	ASSERT_GT(comparison.trial(0).summary().maxDrift, 1.0) << "precondition: stock SI at 10 iterations loses the tower";
	ASSERT_LT(comparison.trial(2).summary().maxDrift, harness::kStandingDriftMeters) << "precondition: the plugin holds it";

	const Image stockA = draw(comparison.trial(0), camera, viewer::ColourMode::Plain);
	const Image stockB = draw(comparison.trial(1), camera, viewer::ColourMode::Plain);
	const Image plugin = draw(comparison.trial(2), camera, viewer::ColourMode::Plain);
	auto differing = [](const Image& a, const Image& b) {
		long count = 0;
		for (size_t i = 0; i < a.rgb.size(); i += 3)
			count += (std::abs(int(a.rgb[i]) - b.rgb[i]) + std::abs(int(a.rgb[i + 1]) - b.rgb[i + 1]) + std::abs(int(a.rgb[i + 2]) - b.rgb[i + 2])) > 30;
		return double(count) / double(a.width * a.height);
	};
	EXPECT_EQ(differing(stockA, stockB), 0.0) << "the same solver gave a different picture";
	EXPECT_GT(differing(stockA, plugin), 0.05) << "the fallen and the standing tower look alike";
}

TEST_F(Headless, LayerColouringPaintsEachTowerBoxInItsLayersColour)
{
	viewer::Comparison comparison({"tower", {{"n", 3}}, {solver(harness::SolverKind::ShockWorld), solver(harness::SolverKind::StockSI)}, kTimeStepSeconds});
	comparison.stepTo(1);
	const viewer::OrbitCamera camera = viewer::pictureCamera(comparison, viewer::StripOptions(), 200.0 / 240.0);
	for (int t = 0; t < comparison.size(); ++t)
	{
		harness::Trial& trial = comparison.trial(t);
		const Image image = draw(trial, camera, viewer::ColourMode::StackLayer);
		const bool plugin = trial.simulation().shockSolver() != nullptr;
		for (int level = 0; level < 3; ++level)
		{
			// The centre of the box's +z face: the camera looks at it from the front right, and nothing
			// stands between (the boxes above and below are outside the line of sight).
			const btRigidBody* box = trial.bodies()[size_t(level)];
			const btVector3 faceCentre = box->getCenterOfMassPosition() + btVector3(0, 0, btScalar(0.5));
			double ndcX = 0, ndcY = 0;
			ASSERT_TRUE(camera.project(faceCentre, 200.0 / 240.0, ndcX, ndcY));
			const int x = int((ndcX + 1) / 2 * image.width), y = int((1 - ndcY) / 2 * image.height);
			ASSERT_TRUE(x >= 0 && x < image.width && y >= 0 && y < image.height);
			const Rgb expected = plugin ? viewer::layerColour(level + 1) : viewer::layerlessColour();
			const unsigned char* p = image.pixel(x, y);
			EXPECT_TRUE(hasHue(p, expected)) << trial.simulation().spec().name() << ", box " << level << " at pixel (" << x << ", " << y
											 << ") is " << int(p[0]) << "," << int(p[1]) << "," << int(p[2]) << ", want the hue of "
											 << expected.r << "," << expected.g << "," << expected.b;
		}
	}
}

TEST(BodyColours, NeighbouringLayersDifferAndThePaletteRepeats)
{
	for (int h = 1; h < 2 * viewer::kLayerPaletteSize; ++h)
	{
		const Rgb a = viewer::layerColour(h), b = viewer::layerColour(h + 1);
		EXPECT_GT(std::fabs(a.r - b.r) + std::fabs(a.g - b.g) + std::fabs(a.b - b.b), 0.3f) << "heights " << h << " and " << h + 1;
	}
	const Rgb first = viewer::layerColour(1), again = viewer::layerColour(1 + viewer::kLayerPaletteSize);
	EXPECT_EQ(first.r, again.r);
	const Rgb unreached = viewer::layerColour(-1), none = viewer::layerlessColour();
	EXPECT_EQ(unreached.g, none.g);
}
}  // namespace
