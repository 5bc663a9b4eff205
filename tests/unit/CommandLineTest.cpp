// The demo programs' shared command-line values (harness/CommandLine.h): what they accept, and a
// message quoting the text for what they refuse (the programs print it and exit with code 2).
#include <harness/CommandLine.h>

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

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
