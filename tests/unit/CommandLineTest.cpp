// The demo programs' shared command-line values (harness/CommandLine.h): what they accept, and a
// message quoting the text for what they refuse (the programs print it and exit with code 2).
#include <harness/CommandLine.h>

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace
{
/// The message of the std::invalid_argument `parse` throws, or "" if it throws none.
template <class F>
std::string refusal(F parse)
{
	try
	{
		parse();
	}
	catch (const std::invalid_argument& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(CommandLine, NumbersAreFiniteAndWhole)
{
	EXPECT_DOUBLE_EQ(harness::parseNumber("1e-3"), 1e-3);
	EXPECT_DOUBLE_EQ(harness::parseNumber("-2.5"), -2.5);
	EXPECT_EQ(refusal([] { harness::parseNumber(""); }), "not a number: ''");
	EXPECT_EQ(refusal([] { harness::parseNumber("1x"); }), "not a number: '1x'");
	EXPECT_EQ(refusal([] { harness::parseNumber("nan"); }), "not a number: 'nan'");
	EXPECT_EQ(refusal([] { harness::parseNumber("inf"); }), "not a number: 'inf'");
}

TEST(CommandLine, IntegersAreWholeAndBounded)
{
	EXPECT_EQ(harness::parseInteger("10"), 10);
	EXPECT_EQ(harness::parseInteger("1e3"), 1000);
	EXPECT_EQ(refusal([] { harness::parseInteger("1.5"); }), "not an integer: '1.5'");
	EXPECT_EQ(refusal([] { harness::parseInteger("1e10"); }), "not an integer: '1e10'");
}

TEST(CommandLine, ListsHaveNoEmptyEntries)
{
	EXPECT_EQ(harness::parseIntegerList("1,10,100", "iteration"), (std::vector<int>{1, 10, 100}));
	EXPECT_EQ(harness::parseNumberList("0,0.5", "f"), (std::vector<double>{0, 0.5}));
	EXPECT_EQ(refusal([] { harness::splitList("si,,sp", "solver"); }), "empty entry in solver list 'si,,sp'");
	EXPECT_EQ(refusal([] { harness::splitList("", "solver"); }), "empty solver list");
	EXPECT_EQ(refusal([] { harness::parseIntegerList("1,x", "iteration"); }), "not a number: 'x'");
}

TEST(CommandLine, SceneParametersAreNameEqualsNumber)
{
	const std::pair<std::string, double> p = harness::parseSceneParam("n=20");
	EXPECT_EQ(p.first, "n");
	EXPECT_DOUBLE_EQ(p.second, 20);
	EXPECT_EQ(refusal([] { harness::parseSceneParam("bricks"); }), "--param wants NAME=VALUE, got 'bricks'");
	EXPECT_EQ(refusal([] { harness::parseSceneParam("=3"); }), "--param wants NAME=VALUE, got '=3'");
	EXPECT_EQ(refusal([] { harness::parseSceneParam("n=ten"); }), "not a number: 'ten'");
}

namespace
{
/// PluginFlags fed `args` as a program's argv (after the program name); every argument must be a plugin flag.
harness::PluginFlags pluginFlags(std::vector<std::string> args)
{
	args.insert(args.begin(), "program");
	std::vector<char*> argv;
	for (std::string& a : args) argv.push_back(&a[0]);
	harness::PluginFlags flags;
	for (int i = 1; i < int(argv.size()); ++i)
		if (!flags.parse(int(argv.size()), argv.data(), i)) throw std::invalid_argument("not a plugin flag: " + args[size_t(i)]);
	return flags;
}
}  // namespace

TEST(CommandLine, PluginFlagsSetSettingsAndExpandEveryCombination)
{
	const std::vector<btShockPropagationSettings> all =
		pluginFlags({"--f", "0,0.25", "--app-friction", "--slop", "0,0.001,0.002", "--bfs-layers"}).expand();
	ASSERT_EQ(all.size(), 6u);
	EXPECT_EQ(all[0].m_weighting, btScalar(0));
	EXPECT_EQ(all[5].m_weighting, btScalar(0.25));
	EXPECT_EQ(all[5].m_correctionSlop, btScalar(0.002));
	for (const btShockPropagationSettings& s : all)
	{
		EXPECT_FALSE(s.m_diagnostics.m_twoFrictionDirections);
		EXPECT_FALSE(s.m_diagnostics.m_supportOrdering);
	}
	EXPECT_EQ(harness::pluginSettingsLabel(all[1]), " f=0 slop=0.001 bfs appfriction");
	EXPECT_EQ(harness::pluginSettingsLabel(btShockPropagationSettings()), " f=0.5") << "defaults: f only";
	EXPECT_EQ(pluginFlags({}).expand().size(), 1u) << "no flag: the base settings alone";
}

TEST(CommandLine, PluginFlagsRefuseBadValues)
{
	EXPECT_NE(refusal([] { pluginFlags({"--f", "1.5"}); }).find("'1.5'"), std::string::npos);
	EXPECT_NE(refusal([] { pluginFlags({"--predictor-sweeps", "2.5"}); }).find("'2.5'"), std::string::npos);
	EXPECT_NE(refusal([] { pluginFlags({"--slop"}); }).find("missing value"), std::string::npos);
}
