#include "viewer/Labels.h"

#include <BulletShockPropagation/btShockPropagationConstraintSolver.h>

#include <imgui.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace viewer
{
namespace
{
const char* kLabelFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
const char* kBoldFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";

std::string format(const char* pattern, double value)
{
	char text[64];
	std::snprintf(text, sizeof(text), pattern, value);
	return text;
}

bool readable(const char* path) { return std::ifstream(path).good(); }
}  // namespace

std::string solverTitle(const harness::SolverSpec& spec)
{
	std::string name;
	switch (spec.kind)
	{
		case harness::SolverKind::StockSI: name = "stock SI"; break;
		case harness::SolverKind::StockSI2Friction: name = "stock SI, 2 friction dirs"; break;
		case harness::SolverKind::NNCG: name = "stock NNCG"; break;
		case harness::SolverKind::MLCPDantzig: name = "stock MLCP (Dantzig)"; break;
		case harness::SolverKind::ShockWorld: name = "shock propagation"; break;
		case harness::SolverKind::ShockSolverOnly: name = "shock propagation, solver only"; break;
	}
	if (spec.substeps > 1) name += ", " + std::to_string(spec.substeps) + " substeps";
	return name + ", " + std::to_string(spec.iterations) + " iterations";
}

std::string formatLength(double metres)
{
	return metres < 1 ? format("%.2f cm", metres * 100) : format("%.2f m", metres);
}

std::vector<std::string> metricLines(harness::Trial& trial)
{
	std::vector<std::string> lines;
	if (trial.steps() == 0) return {"not stepped yet"};
	const harness::TrialSeries& s = trial.series();
	const harness::TrialSummary sum = trial.summary();
	lines.push_back("drift " + formatLength(s.drift.back()) + " (max " + formatLength(sum.maxDrift) + ")");
	lines.push_back(format("penetration %.2f mm", s.penetration.back() * 1e3) + format(" (max %.2f)", sum.maxPenetration * 1e3));
	lines.push_back(format("ground / weight %.2f", s.groundOverWeight.back()));
	lines.push_back(format("%.2f ms/step", sum.msPerStep));
	const btShockPropagationConstraintSolver* solver = trial.simulation().shockSolver();
	lines.push_back(solver ? "stack layers " + std::to_string(solver->getStatistics().m_numLayers) : "stack layers: none (stock)");
	return lines;
}

float drawTextBlock(ImDrawList& list, float x, float y, const std::vector<std::string>& lines, bool titleFirst, float maxWidth)
{
	ImFont* regular = ImGui::GetIO().Fonts->Fonts[0];
	ImFont* bold = ImGui::GetIO().Fonts->Fonts.Size > 1 ? ImGui::GetIO().Fonts->Fonts[1] : regular;
	const float pad = 4, gap = 1;
	float size = regular->FontSize, width = 0;
	for (size_t i = 0; i < lines.size(); ++i)
	{
		ImFont* font = titleFirst && i == 0 ? bold : regular;
		width = std::max(width, font->CalcTextSizeA(size, 1e6f, 0, lines[i].c_str()).x);
	}
	if (maxWidth > 0 && width + 2 * pad > maxWidth)
	{
		const float scale = std::max(0.6f, (maxWidth - 2 * pad) / width);  // below 60% it is unreadable anyway
		size *= scale;
		width *= scale;
	}
	const float height = float(lines.size()) * (size + gap);
	list.AddRectFilled(ImVec2(x, y), ImVec2(x + width + 2 * pad, y + height + 2 * pad), IM_COL32(255, 255, 255, 200), 3);
	float row = y + pad;
	for (size_t i = 0; i < lines.size(); ++i)
	{
		ImFont* font = titleFirst && i == 0 ? bold : regular;
		list.AddText(font, size, ImVec2(x + pad, row), IM_COL32(20, 20, 25, 255), lines[i].c_str());
		row += size + gap;
	}
	return height + 2 * pad;
}

void loadLabelFont(float pixels)
{
	ImGuiIO& io = ImGui::GetIO();
	if (readable(kLabelFontPath) && readable(kBoldFontPath))
	{
		io.Fonts->AddFontFromFileTTF(kLabelFontPath, pixels);
		io.Fonts->AddFontFromFileTTF(kBoldFontPath, pixels);
	}
	else
	{
		io.Fonts->AddFontDefault();
	}
}

OffscreenText::OffscreenText(float fontPixels) : m_fontPixels(fontPixels)
{
	m_previous = ImGui::GetCurrentContext();
	m_context = ImGui::CreateContext();
	ImGui::SetCurrentContext(m_context);
	ImGui::GetIO().IniFilename = nullptr;
	loadLabelFont(fontPixels);
	ImGui_ImplOpenGL3_Init("#version 330 core");
	ImGui::SetCurrentContext(m_previous);
}

OffscreenText::~OffscreenText()
{
	ImGui::SetCurrentContext(m_context);
	ImGui_ImplOpenGL3_Shutdown();
	ImGui::DestroyContext(m_context);
	ImGui::SetCurrentContext(m_previous);
}

ImDrawList& OffscreenText::begin(int width, int height)
{
	m_previous = ImGui::GetCurrentContext();
	ImGui::SetCurrentContext(m_context);
	ImGuiIO& io = ImGui::GetIO();
	io.DisplaySize = ImVec2(float(width), float(height));
	io.DeltaTime = 1.0f / 60.0f;
	ImGui_ImplOpenGL3_NewFrame();
	ImGui::NewFrame();
	return *ImGui::GetForegroundDrawList();
}

void OffscreenText::end()
{
	ImGui::Render();
	ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
	ImGui::SetCurrentContext(m_previous);
}
}  // namespace viewer
