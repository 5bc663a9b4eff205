// bsp_viewer on bad input and without a display: clear messages, exit codes, never a crash; and
// the headless command writes the PNG it promises.
#include <viewer/Png.h>

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace
{
struct ProcessResult
{
	int exitCode = -1;
	std::string output;  // stdout and stderr
};

/// Runs bsp_viewer with `arguments` under `environment` (prefix of `env`, e.g. "-u DISPLAY").
ProcessResult viewerRun(const std::string& environment, const std::string& arguments)
{
	const std::string command = "env " + environment + " '" BSP_VIEWER_PATH "' " + arguments + " 2>&1";
	ProcessResult run;
	FILE* pipe = popen(command.c_str(), "r");
	if (!pipe) return run;
	std::array<char, 4096> buffer;
	size_t n = 0;
	while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) run.output.append(buffer.data(), n);
	const int status = pclose(pipe);
	run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
	return run;
}

const char* kNoDisplay = "-u DISPLAY -u WAYLAND_DISPLAY";

TEST(ViewerCommandLine, UnknownSceneListsTheValidOnesAndExitsWith2)
{
	const ProcessResult run = viewerRun(kNoDisplay, "--scene no_such_scene --headless --out /dev/null");
	EXPECT_EQ(run.exitCode, 2) << run.output;
	EXPECT_NE(run.output.find("unknown scene 'no_such_scene'"), std::string::npos) << run.output;
	EXPECT_NE(run.output.find("round_tower"), std::string::npos) << "valid names missing: " << run.output;
}

TEST(ViewerCommandLine, UnknownSolverAndBadParameterExitWith2)
{
	ProcessResult run = viewerRun(kNoDisplay, "--solvers si,nope --headless --out /dev/null");
	EXPECT_EQ(run.exitCode, 2) << run.output;
	EXPECT_NE(run.output.find("unknown solver 'nope'"), std::string::npos) << run.output;
	run = viewerRun(kNoDisplay, "--scene tower --param bricks=3 --headless --out /dev/null");
	EXPECT_EQ(run.exitCode, 2) << run.output;
	EXPECT_NE(run.output.find("bricks"), std::string::npos) << run.output;
}

TEST(ViewerCommandLine, WindowWithoutDisplaySaysSoAndPointsToHeadless)
{
	const ProcessResult run = viewerRun(kNoDisplay, "--scene tower");
	EXPECT_EQ(run.exitCode, 1) << run.output;
	EXPECT_NE(run.output.find("no display"), std::string::npos) << run.output;
	EXPECT_NE(run.output.find("--headless"), std::string::npos) << run.output;
}

TEST(ViewerCommandLine, HeadlessWithoutAnyOffscreenContextSaysWhy)
{
	const ProcessResult run = viewerRun(std::string(kNoDisplay) + " BSP_VIEWER_NO_EGL=1", "--scene tower --param n=2 --headless --out /dev/null");
	EXPECT_EQ(run.exitCode, 1) << run.output;
	EXPECT_NE(run.output.find("no offscreen OpenGL 3.3 context"), std::string::npos) << run.output;
}

TEST(ViewerCommandLine, HeadlessWritesAStripOfSolversByTimes)
{
	const std::string path = ::testing::TempDir() + "bsp_viewer_strip.png";
	std::remove(path.c_str());
	const ProcessResult run = viewerRun(kNoDisplay, "--scene tower --param n=3 --solvers si,sp --times 0.1,0.2 --size 64x48 --headless --out '" + path + "'");
	ASSERT_EQ(run.exitCode, 0) << run.output;
	viewer::Image image;
	std::string error;
	ASSERT_TRUE(viewer::readPng(path, image, error)) << error;
	EXPECT_EQ(image.width, 2 * 64 + 2);  // two columns and the gutter between them
	EXPECT_GT(image.height, 2 * 48);     // two rows, each with its label band
	std::remove(path.c_str());
}
}  // namespace
