#include "Interactive.h"

#include "viewer/Labels.h"

#include "Gl.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <scenes/Registry.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace viewer
{
namespace
{
/// Width of the control panel on the left (pixels).
const float kPanelWidth = 340;
/// Most viewports side by side.
const int kMaxViewports = 4;

const harness::SolverKind kKinds[] = {harness::SolverKind::StockSI, harness::SolverKind::StockSI2Friction, harness::SolverKind::NNCG,
									  harness::SolverKind::MLCPDantzig, harness::SolverKind::ShockWorld, harness::SolverKind::ShockSolverOnly};

/// A titled separator (ImGui 1.86 has no SeparatorText).
void section(const char* title)
{
	ImGui::Spacing();
	ImGui::Separator();
	ImGui::TextUnformatted(title);
}

std::string kindName(harness::SolverKind kind)
{
	harness::SolverSpec s;
	s.kind = kind;
	return s.name();
}

/// Everything the window shows and edits.
class App
{
public:
	App(GLFWwindow* window, const ComparisonSetup& setup, const DrawOptions& draw, const OrbitCamera& camera)
		: m_window(window), m_setup(setup), m_draw(draw), m_comparison(new Comparison(setup)), m_camera(camera)
	{
		m_weighting = float(setup.solvers.front().settings.m_weighting);
		m_frameCamera = true;
	}

	void frame();

private:
	void rebuild();
	void handleInput();
	void shootAt(double windowX, double windowY);
	void drawPanel();
	std::vector<Viewport> viewports(int framebufferWidth, int framebufferHeight) const;

	GLFWwindow* m_window;
	ComparisonSetup m_setup;
	DrawOptions m_draw;
	std::unique_ptr<Comparison> m_comparison;
	Renderer m_renderer;
	OrbitCamera m_camera;
	bool m_paused = false, m_stepOnce = false, m_frameCamera = false;
	float m_weighting = 0.5f;
	float m_shotSpeed = 12, m_shotEdge = 0.5f, m_shotMass = 5;
	std::string m_error;
	double m_lastX = 0, m_lastY = 0;
	bool m_dragging[2] = {false, false};
};

std::vector<Viewport> App::viewports(int width, int height) const
{
	// Window and framebuffer may differ on scaled displays; the panel width is in window units.
	int windowWidth = 1, windowHeight = 1;
	glfwGetWindowSize(m_window, &windowWidth, &windowHeight);
	const int panel = int(kPanelWidth * float(width) / float(std::max(1, windowWidth)));
	const int n = m_comparison->size();
	const int each = std::max(1, (width - panel) / n);
	std::vector<Viewport> out;
	for (int i = 0; i < n; ++i)
	{
		Viewport v;
		v.x = panel + i * each;
		v.y = 0;
		v.width = std::max(1, each - 2);
		v.height = std::max(1, height);
		out.push_back(v);
	}
	return out;
}

void App::rebuild()
{
	try
	{
		for (harness::SolverSpec& s : m_setup.solvers) s.settings.m_weighting = btScalar(m_weighting);
		m_comparison.reset(new Comparison(m_setup));
		m_error.clear();
	}
	catch (const std::exception& e)
	{
		m_error = e.what();  // keep showing the previous comparison
	}
}

void App::shootAt(double windowX, double windowY)
{
	int fbWidth = 1, fbHeight = 1, windowWidth = 1, windowHeight = 1;
	glfwGetFramebufferSize(m_window, &fbWidth, &fbHeight);
	glfwGetWindowSize(m_window, &windowWidth, &windowHeight);
	const double px = windowX * fbWidth / std::max(1, windowWidth);
	const double py = fbHeight - windowY * fbHeight / std::max(1, windowHeight);
	for (const Viewport& v : viewports(fbWidth, fbHeight))
	{
		if (px < v.x || px >= v.x + v.width) continue;
		const double ndcX = 2 * (px - v.x) / v.width - 1, ndcY = 2 * (py - v.y) / v.height - 1;
		btVector3 origin, direction;
		m_camera.ray(ndcX, ndcY, v.aspect(), origin, direction);
		// Start a little in front of the eye so the box is visible on its way.
		m_comparison->shootBox(origin + direction * btScalar(1.0), direction, m_shotSpeed, m_shotEdge, m_shotMass);
		return;
	}
}

void App::handleInput()
{
	ImGuiIO& io = ImGui::GetIO();
	double x = 0, y = 0;
	glfwGetCursorPos(m_window, &x, &y);
	const double dx = x - m_lastX, dy = y - m_lastY;
	m_lastX = x;
	m_lastY = y;
	if (!io.WantCaptureMouse)
	{
		const bool shift = io.KeyShift;
		if (ImGui::IsMouseClicked(ImGuiMouseButton_Middle) || (shift && ImGui::IsMouseClicked(ImGuiMouseButton_Left)))
			shootAt(x, y);
		else if (ImGui::IsMouseClicked(ImGuiMouseButton_Left))
			m_dragging[0] = true;
		if (ImGui::IsMouseClicked(ImGuiMouseButton_Right)) m_dragging[1] = true;
		if (io.MouseWheel != 0) m_camera.zoom(std::pow(0.9, double(io.MouseWheel)));
	}
	if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) m_dragging[0] = false;
	if (!ImGui::IsMouseDown(ImGuiMouseButton_Right)) m_dragging[1] = false;
	if (m_dragging[0]) m_camera.orbit(-dx * 0.008, dy * 0.008);
	int windowHeight = 1;
	glfwGetWindowSize(m_window, nullptr, &windowHeight);
	if (m_dragging[1]) m_camera.pan(-dx / std::max(1, windowHeight), dy / std::max(1, windowHeight));

	if (!io.WantCaptureKeyboard)
	{
		if (ImGui::IsKeyPressed(GLFW_KEY_SPACE)) m_paused = !m_paused;
		if (ImGui::IsKeyPressed(GLFW_KEY_S)) { m_paused = true; m_stepOnce = true; }
		if (ImGui::IsKeyPressed(GLFW_KEY_R)) rebuild();
		if (ImGui::IsKeyPressed(GLFW_KEY_F)) m_frameCamera = true;
		if (ImGui::IsKeyPressed(GLFW_KEY_C)) m_draw.contacts = !m_draw.contacts;
		if (ImGui::IsKeyPressed(GLFW_KEY_L))
			m_draw.colours = m_draw.colours == ColourMode::StackLayer ? ColourMode::Plain : ColourMode::StackLayer;
	}
}

void App::drawPanel()
{
	ImGui::SetNextWindowPos(ImVec2(0, 0));
	ImGui::SetNextWindowSize(ImVec2(kPanelWidth, ImGui::GetIO().DisplaySize.y));
	ImGui::Begin("BulletShockPropagation", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);

	// Scene picker over the registry, with its parameters.
	const scenes::SceneEntry* entry = scenes::findScene(m_setup.scene);
	if (ImGui::BeginCombo("scene", m_setup.scene.c_str()))
	{
		for (const scenes::SceneEntry& e : scenes::registry())
		{
			const std::string label = e.category + " / " + e.name;
			if (ImGui::Selectable(label.c_str(), e.name == m_setup.scene) && e.name != m_setup.scene)
			{
				m_setup.scene = e.name;
				m_setup.params.clear();
				m_frameCamera = true;
				rebuild();
			}
			if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", e.description.c_str());
		}
		ImGui::EndCombo();
	}
	if (entry)
	{
		ImGui::TextWrapped("%s", entry->description.c_str());
		if (ImGui::TreeNode("scene parameters"))
		{
			for (const scenes::Param& p : entry->defaults)
			{
				double value = p.value;
				for (const auto& kv : m_setup.params)
					if (kv.first == p.name) value = kv.second;
				ImGui::InputDouble((p.name + " (" + p.unit + ")").c_str(), &value, 0, 0, "%.4g");
				if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", p.description.c_str());
				if (ImGui::IsItemDeactivatedAfterEdit())
				{
					auto found = std::find_if(m_setup.params.begin(), m_setup.params.end(), [&](const auto& kv) { return kv.first == p.name; });
					if (found != m_setup.params.end())
						found->second = value;
					else
						m_setup.params.push_back({p.name, value});
					m_frameCamera = true;
					rebuild();
				}
			}
			ImGui::TreePop();
		}
	}
	if (!m_error.empty()) ImGui::TextColored(ImVec4(0.9f, 0.2f, 0.2f, 1), "%s", m_error.c_str());

	section("viewports (changes restart)");
	int remove = -1;
	for (size_t i = 0; i < m_setup.solvers.size(); ++i)
	{
		harness::SolverSpec& s = m_setup.solvers[i];
		ImGui::PushID(int(i));
		ImGui::SetNextItemWidth(110);
		if (ImGui::BeginCombo("##kind", s.name().c_str()))
		{
			for (harness::SolverKind kind : kKinds)
				if (ImGui::Selectable(kindName(kind).c_str(), kind == s.kind))
				{
					s.kind = kind;
					rebuild();
				}
			ImGui::EndCombo();
		}
		ImGui::SameLine();
		ImGui::SetNextItemWidth(120);
		ImGui::SliderInt("##iterations", &s.iterations, 1, 200, "%d iterations");
		if (ImGui::IsItemDeactivatedAfterEdit()) rebuild();
		if (m_setup.solvers.size() > 1)
		{
			ImGui::SameLine();
			if (ImGui::SmallButton("x")) remove = int(i);
		}
		ImGui::PopID();
	}
	if (remove >= 0)
	{
		m_setup.solvers.erase(m_setup.solvers.begin() + remove);
		rebuild();
	}
	if (int(m_setup.solvers.size()) < kMaxViewports && ImGui::Button("add viewport"))
	{
		m_setup.solvers.push_back(m_setup.solvers.back());
		rebuild();
	}
	ImGui::SliderFloat("f (plugin)", &m_weighting, 0, 1, "%.3f");
	if (ImGui::IsItemDeactivatedAfterEdit()) rebuild();
	float dtMs = float(m_setup.timeStep * 1e3);
	ImGui::SliderFloat("time step", &dtMs, 2, 50, "%.2f ms");
	if (ImGui::IsItemDeactivatedAfterEdit())
	{
		m_setup.timeStep = double(dtMs) * 1e-3;
		rebuild();
	}

	section("run");
	if (ImGui::Button(m_paused ? "run (space)" : "pause (space)")) m_paused = !m_paused;
	ImGui::SameLine();
	if (ImGui::Button("step (S)"))
	{
		m_paused = true;
		m_stepOnce = true;
	}
	ImGui::SameLine();
	if (ImGui::Button("reset (R)")) rebuild();
	ImGui::SameLine();
	if (ImGui::Button("frame (F)")) m_frameCamera = true;
	ImGui::Text("t = %.3f s, frame %d, %d box(es) shot", m_comparison->time(), m_comparison->steps(), m_comparison->shotBoxes());

	section("draw");
	int mode = int(m_draw.colours);
	ImGui::RadioButton("stack layers (L)", &mode, int(ColourMode::StackLayer));
	ImGui::SameLine();
	ImGui::RadioButton("drift", &mode, int(ColourMode::Drift));
	ImGui::SameLine();
	ImGui::RadioButton("plain", &mode, int(ColourMode::Plain));
	m_draw.colours = ColourMode(mode);
	if (m_draw.colours == ColourMode::Drift) ImGui::TextWrapped("red: moved 1 cm or more from the start (\"fallen\")");
	if (m_draw.colours == ColourMode::StackLayer)
	{
		ImGui::TextUnformatted("height");
		for (int h = 1; h <= kLayerPaletteSize; ++h)
		{
			const Rgb c = layerColour(h);
			ImGui::SameLine();
			ImGui::ColorButton(("height " + std::to_string(h) + (h == kLayerPaletteSize ? " (then repeats)" : "")).c_str(),
							   ImVec4(c.r, c.g, c.b, 1), ImGuiColorEditFlags_NoPicker, ImVec2(14, 14));
		}
		ImGui::TextWrapped("1 = on the ground. Stock solvers have no layers (sandstone).");
	}
	ImGui::Checkbox("contacts and normal forces (C)", &m_draw.contacts);
	if (m_draw.contacts)
	{
		float scale = float(m_draw.forceScale);
		ImGui::SliderFloat("force scale", &scale, 0.01f, 2, "%.2f m / weight", ImGuiSliderFlags_Logarithmic);
		m_draw.forceScale = double(scale);
		ImGui::TextWrapped("red line: normal force, %.2f m per mean body weight", m_draw.forceScale);
	}

	section("shoot a box (middle click or shift + click)");
	ImGui::SliderFloat("speed", &m_shotSpeed, 1, 40, "%.1f m/s");
	ImGui::SliderFloat("edge", &m_shotEdge, 0.1f, 2, "%.2f m");
	ImGui::SliderFloat("mass", &m_shotMass, 0.1f, 100, "%.1f kg", ImGuiSliderFlags_Logarithmic);

	section("camera");
	ImGui::TextWrapped("left drag: orbit, right drag: pan, wheel: zoom");
	ImGui::End();
}

void App::frame()
{
	int fbWidth = 1, fbHeight = 1;
	glfwGetFramebufferSize(m_window, &fbWidth, &fbHeight);
	handleInput();
	if (!m_paused || m_stepOnce) m_comparison->step();
	m_stepOnce = false;

	const std::vector<Viewport> views = viewports(fbWidth, fbHeight);
	if (m_frameCamera)
	{
		btVector3 lo, hi;
		if (bodyBounds(m_comparison->trial(0).bodies(), lo, hi))
		{
			lo.setY(btMin(lo.y(), btScalar(0)));
			m_camera.frame(lo, hi, views.front().aspect());
		}
		m_frameCamera = false;
	}

	glBindFramebuffer(GL_FRAMEBUFFER, 0);
	glViewport(0, 0, fbWidth, fbHeight);
	glDisable(GL_SCISSOR_TEST);
	glClearColor(0.15f, 0.15f, 0.17f, 1);
	glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
	for (int i = 0; i < m_comparison->size(); ++i) m_renderer.drawTrial(m_comparison->trial(i), m_camera, views[size_t(i)], m_draw);

	drawPanel();
	// Live overlay per viewport: solver, then the demo program's metrics.
	int windowWidth = 1;
	glfwGetWindowSize(m_window, &windowWidth, nullptr);
	const float toWindow = float(windowWidth) / float(std::max(1, fbWidth));
	for (int i = 0; i < m_comparison->size(); ++i)
	{
		harness::Trial& trial = m_comparison->trial(i);
		std::vector<std::string> lines{solverTitle(trial.simulation().spec())};
		if (trial.simulation().spec().isPlugin())
		{
			char f[32];
			std::snprintf(f, sizeof(f), "f = %.3g", double(trial.simulation().spec().settings.m_weighting));
			lines.push_back(f);
		}
		for (const std::string& l : metricLines(trial)) lines.push_back(l);
		drawTextBlock(*ImGui::GetBackgroundDrawList(), float(views[size_t(i)].x) * toWindow + 6, 6, lines, true,
					  float(views[size_t(i)].width) * toWindow - 12);
	}
}

}  // namespace

int runInteractive(const ComparisonSetup& setup, const DrawOptions& draw, const OrbitCamera& camera)
{
	if (!glfwInit())
	{
		const char* description = nullptr;
		glfwGetError(&description);
		std::cerr << "bsp_viewer: cannot open a window: no display (" << (description ? description : "GLFW cannot start") << ").\n"
				  << "The interactive viewer needs a display (X11 or Wayland). Without one, render pictures headless\n"
				  << "(EGL, no display needed), e.g.:\n"
				  << "  bsp_viewer --headless --out wall.png --scene wall --times 2,4\n";
		return 1;
	}
	glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
	glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
	glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
	glfwWindowHint(GLFW_SAMPLES, 4);
	GLFWwindow* window = glfwCreateWindow(1600, 900, "BulletShockPropagation viewer", nullptr, nullptr);
	if (!window)
	{
		const char* description = nullptr;
		glfwGetError(&description);
		std::cerr << "bsp_viewer: cannot open an OpenGL 3.3 window (" << (description ? description : "unknown error") << ").\n"
				  << "Render pictures headless instead: bsp_viewer --headless --out wall.png --scene wall\n";
		glfwTerminate();
		return 1;
	}
	glfwMakeContextCurrent(window);
	glfwSwapInterval(1);

	IMGUI_CHECKVERSION();
	ImGui::CreateContext();
	ImGui::GetIO().IniFilename = nullptr;
	loadLabelFont(15);
	ImGui_ImplGlfw_InitForOpenGL(window, true);
	ImGui_ImplOpenGL3_Init("#version 330 core");
	{
		App app(window, setup, draw, camera);
		while (!glfwWindowShouldClose(window))
		{
			glfwPollEvents();
			ImGui_ImplOpenGL3_NewFrame();
			ImGui_ImplGlfw_NewFrame();
			ImGui::NewFrame();
			app.frame();
			ImGui::Render();
			ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
			glfwSwapBuffers(window);
		}
	}
	ImGui_ImplOpenGL3_Shutdown();
	ImGui_ImplGlfw_Shutdown();
	ImGui::DestroyContext();
	glfwDestroyWindow(window);
	glfwTerminate();
	return 0;
}
}  // namespace viewer
