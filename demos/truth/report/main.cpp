// bsp_truth: every case of the truth suite (truth::truthCases()) under a list of solver
// configurations; writes a CSV (demos/charts/results/truth.csv by default, read by
// demos/charts/plot_charts.py for the truth_vs_cost chart) and a markdown table (cases x
// configurations, PASS/FAIL and the figure). Not part of the shipped plugin.
//
// --grid runs the shape grid's cases (truth::gridCases(), include/truth/GridCases.h) instead: the
// CSV defaults to demos/charts/results/truth_grid.csv (the truth_vs_cost_grid chart) and the markdown
// adds a passed row per group (grid_column, grid_round, grid_structure, grid_slides, grid_stays).
//
// MLCP runs each case in a child process under a time limit (--timeout, 20 s): a case it cannot
// finish in time is marked "skipped". It runs after the other configurations of the same case, so
// the case's cached reference is already computed when the child is forked.
#include <harness/CommandLine.h>
#include <truth/GridCases.h>
#include <truth/TruthCase.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <signal.h>
#include <sys/select.h>
#include <sys/wait.h>
#include <unistd.h>

namespace
{
const char* kUsage =
	"usage: bsp_truth [--grid] [--configs LIST] [--cases LIST] [--csv FILE] [--md FILE] [--timeout S] [--list]\n"
	"  --grid     the shape grid's 105 cases (columns, round bodies on a block, tables and plank cribs stand, a stack off a table's edge falls, pushed stacks slide / stay, per shape and ground)\n"
	"             instead of the truth suite's; --cases and --list then name grid cases\n"
	"  --configs  comma-separated solver:iterations, e.g. si:10,si-sub4:10,sp:5,mlcp (iterations default 10);\n"
	"             default: si at 1,2,5,10,20,50,100,200; si2f:10; si-sub2/4/8 at 10; nncg at 10, 50; mlcp;\n"
	"             sp and sp-solver at 5, 10, 20; sp-classic:10\n"
	"  --cases    comma-separated case or group names (default: every case)\n"
	"  --csv      CSV output (default demos/charts/results/truth.csv under the source tree; truth_grid.csv with --grid)\n"
	"  --md       markdown table output (default: standard output)\n"
	"  --timeout  seconds an MLCP case may take before it is skipped (default 20)\n"
	"  --list     print the cases and exit\n"
	"  plugin flags (below) apply to the plugin's configurations; a flag with a comma list runs each variant\n";

struct Config
{
	harness::SolverSpec spec;
	std::string column;  // e.g. "si 10", "si-sub4 10", "mlcp"
};

struct Result
{
	bool skipped = false;
	truth::Verdict verdict;
};

std::vector<std::string> split(const std::string& text)
{
	std::vector<std::string> out;
	std::stringstream in(text);
	std::string item;
	while (std::getline(in, item, ','))
		if (!item.empty()) out.push_back(item);
	return out;
}

bool isMLCP(const harness::SolverSpec& spec) { return spec.kind == harness::SolverKind::MLCPDantzig; }

bool parseConfig(const std::string& token, Config& config, std::string& error)
{
	const std::string::size_type colon = token.find(':');
	const std::string name = token.substr(0, colon);
	if (!harness::parseSolverKind(name, config.spec, error)) return false;
	config.spec.iterations = 10;
	if (colon != std::string::npos)
	{
		char* end = nullptr;
		const long n = std::strtol(token.c_str() + colon + 1, &end, 10);
		if (*end != '\0' || n < 1 || n > 100000)
		{
			error = "bad iteration count in '" + token + "'";
			return false;
		}
		config.spec.iterations = int(n);
	}
	config.column = isMLCP(config.spec) ? config.spec.name() : config.spec.name() + " " + std::to_string(config.spec.iterations);
	return true;
}

std::string defaultConfigs()
{
	return "si:1,si:2,si:5,si:10,si:20,si:50,si:100,si:200,si2f:10,si-sub2:10,si-sub4:10,si-sub8:10,nncg:10,nncg:50,mlcp,"
		   "sp:5,sp:10,sp:20,sp-solver:5,sp-solver:10,sp-solver:20,sp-classic:10";
}

// Verdict through a pipe: one line of numbers, then unit and detail on their own lines.
std::string serialise(const truth::Verdict& v)
{
	std::ostringstream out;
	out.precision(17);
	out << int(v.pass) << " " << v.figure << " " << v.expected << " " << v.msPerStep << "\n" << v.unit << "\n" << v.detail << "\n";
	return out.str();
}

bool deserialise(const std::string& text, truth::Verdict& v)
{
	std::istringstream in(text);
	int pass = 0;
	std::string figure, expected, ms;  // strings: "inf" and "nan" do not parse as doubles with >>
	if (!(in >> pass >> figure >> expected >> ms)) return false;
	v.pass = pass != 0;
	v.figure = std::strtod(figure.c_str(), nullptr);
	v.expected = std::strtod(expected.c_str(), nullptr);
	v.msPerStep = std::strtod(ms.c_str(), nullptr);
	in.ignore(1);
	std::getline(in, v.unit);
	std::getline(in, v.detail);
	return true;
}

/// Runs the case in a child process; skipped if it does not finish within `timeoutSeconds`.
Result runWithTimeout(const truth::TruthCase& c, const harness::SolverSpec& spec, double timeoutSeconds)
{
	Result result;
	int fds[2];
	if (pipe(fds) != 0)
	{
		result.verdict = c.run(spec);
		return result;
	}
	std::cout.flush();
	std::cerr.flush();
	const pid_t child = fork();
	if (child == 0)
	{
		close(fds[0]);
		const std::string text = serialise(c.run(spec));
		const ssize_t written = write(fds[1], text.data(), text.size());
		close(fds[1]);
		_exit(written == ssize_t(text.size()) ? 0 : 1);
	}
	close(fds[1]);
	if (child < 0)
	{
		close(fds[0]);
		result.verdict = c.run(spec);
		return result;
	}
	std::string text;
	const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
	bool done = false;
	while (!done)
	{
		const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
		if (left <= 0) break;
		fd_set set;
		FD_ZERO(&set);
		FD_SET(fds[0], &set);
		timeval tv;
		tv.tv_sec = long(left);
		tv.tv_usec = long((left - double(tv.tv_sec)) * 1e6);
		const int ready = select(fds[0] + 1, &set, nullptr, nullptr, &tv);
		if (ready < 0 && errno == EINTR) continue;
		if (ready <= 0) break;
		char buffer[4096];
		const ssize_t n = read(fds[0], buffer, sizeof buffer);
		if (n <= 0)
			done = true;  // EOF: the child wrote everything and exited
		else
			text.append(buffer, size_t(n));
	}
	close(fds[0]);
	if (!done) kill(child, SIGKILL);
	int status = 0;
	waitpid(child, &status, 0);
	if (!done || !deserialise(text, result.verdict))
	{
		result.skipped = true;
		result.verdict.detail = done ? "the child process failed" : "skipped: longer than " + std::to_string(int(timeoutSeconds)) + " s";
	}
	return result;
}

std::string csvQuote(const std::string& text)
{
	std::string out = "\"";
	for (char ch : text)
	{
		if (ch == '"') out += '"';
		out += ch;
	}
	return out + "\"";
}

std::string figureText(double value)
{
	char buffer[64];
	if (!std::isfinite(value)) return std::isnan(value) ? "nan" : "inf";
	std::snprintf(buffer, sizeof buffer, "%.4g", value);
	return buffer;
}

std::string sourceTree()
{
#ifdef BSP_SOURCE_DIR
	return BSP_SOURCE_DIR;
#else
	return ".";
#endif
}
}  // namespace

int main(int argc, char** argv)
{
	// --grid anywhere on the line picks the case list before --list and --cases read it.
	bool grid = false;
	for (int i = 1; i < argc; ++i)
		grid = grid || std::string(argv[i]) == "--grid";
	const std::vector<truth::TruthCase>& allCases = grid ? truth::gridCases() : truth::truthCases();
	std::string configList = defaultConfigs(), caseList, mdPath;
	std::string csvPath = sourceTree() + (grid ? "/demos/charts/results/truth_grid.csv" : "/demos/charts/results/truth.csv");
	double timeout = 20;
	harness::PluginFlags plugin;  // applied to the plugin's configurations, every combination
	bool pluginFlagsGiven = false;
	for (int i = 1; i < argc; ++i)
	{
		const std::string arg = argv[i];
		auto value = [&]() -> std::string {
			if (i + 1 >= argc)
			{
				std::cerr << arg << " needs a value\n" << kUsage;
				std::exit(2);
			}
			return argv[++i];
		};
		if (arg == "--grid") continue;  // read above
		else if (arg == "--configs") configList = value();
		else if (arg == "--cases") caseList = value();
		else if (arg == "--csv") csvPath = value();
		else if (arg == "--md") mdPath = value();
		else if (arg == "--timeout") timeout = std::atof(value().c_str());
		else if (arg == "--list")
		{
			for (const truth::TruthCase& c : allCases)
				std::cout << c.name << " (" << c.group << "): " << c.statement << "\n";
			return 0;
		}
		else if (arg == "--help" || arg == "-h")
		{
			std::cout << kUsage;
			harness::PluginFlags::printUsage(std::cout);
			return 0;
		}
		else
		{
			try
			{
				if (plugin.parse(argc, argv, i))
				{
					pluginFlagsGiven = true;
					continue;
				}
			}
			catch (const std::invalid_argument& e)
			{
				std::cerr << e.what() << "\n";
				return 2;
			}
			std::cerr << "unknown option " << arg << "\n" << kUsage;
			return 2;
		}
	}

	std::vector<Config> configs;
	for (const std::string& token : split(configList))
	{
		Config config;
		std::string error;
		if (!parseConfig(token, config, error))
		{
			std::cerr << error << "\n";
			return 2;
		}
		if (!config.spec.isPlugin())
		{
			configs.push_back(config);
			continue;
		}
		for (const btShockPropagationSettings& settings : plugin.expand(config.spec.settings))
		{
			Config variant = config;
			variant.spec.settings = settings;
			if (pluginFlagsGiven) variant.column += harness::pluginSettingsLabel(settings);
			configs.push_back(variant);
		}
	}
	std::vector<const truth::TruthCase*> cases;
	const std::vector<std::string> wanted = split(caseList);
	for (const std::string& w : wanted)
	{
		bool known = false;
		for (const truth::TruthCase& c : allCases)
			known = known || c.name == w || c.group == w;
		if (!known)
		{
			std::cerr << "unknown case or group '" << w << "' (--list shows them)\n";
			return 2;
		}
	}
	for (const truth::TruthCase& c : allCases)
	{
		bool take = wanted.empty();
		for (const std::string& w : wanted)
			take = take || c.name == w || c.group == w;
		if (take) cases.push_back(&c);
	}
	if (cases.empty() || configs.empty())
	{
		std::cerr << "nothing to run: " << cases.size() << " cases, " << configs.size() << " configurations\n";
		return 2;
	}

	const auto start = std::chrono::steady_clock::now();
	// results[case][config]
	std::vector<std::vector<Result>> results(cases.size(), std::vector<Result>(configs.size()));
	for (size_t ci = 0; ci < cases.size(); ++ci)
	{
		// MLCP last, in a child under the time limit (the reference is cached by then).
		for (int pass = 0; pass < 2; ++pass)
		{
			for (size_t k = 0; k < configs.size(); ++k)
			{
				if (isMLCP(configs[k].spec) != (pass == 1)) continue;
				const auto t0 = std::chrono::steady_clock::now();
				Result& r = results[ci][k];
				if (pass == 1)
					r = runWithTimeout(*cases[ci], configs[k].spec, timeout);
				else
					r.verdict = cases[ci]->run(configs[k].spec);
				const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
				std::cerr << cases[ci]->name << " / " << configs[k].column << ": "
						  << (r.skipped ? "skipped" : r.verdict.pass ? "PASS" : "FAIL") << " " << figureText(r.verdict.figure) << " "
						  << r.verdict.unit << " (" << figureText(seconds) << " s)\n";
			}
		}
	}
	const double totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

	std::ofstream csv(csvPath);
	if (!csv)
	{
		std::cerr << "cannot write " << csvPath << "\n";
		return 1;
	}
	csv << "case,group,config,iterations,pass,figure,expected,unit,msPerStep,detail\n";
	for (size_t ci = 0; ci < cases.size(); ++ci)
	{
		for (size_t k = 0; k < configs.size(); ++k)
		{
			const Result& r = results[ci][k];
			const truth::Verdict& v = r.verdict;
			csv << cases[ci]->name << "," << cases[ci]->group << "," << configs[k].spec.name() << "," << configs[k].spec.iterations << ","
				<< (r.skipped ? "skipped" : v.pass ? "1" : "0") << "," << (r.skipped ? "" : figureText(v.figure)) << ","
				<< (r.skipped ? "" : figureText(v.expected)) << "," << v.unit << "," << (r.skipped ? "" : figureText(v.msPerStep)) << ","
				<< csvQuote(v.detail) << "\n";
		}
	}

	std::ostringstream md;
	md << "| case |";
	for (const Config& c : configs) md << " " << c.column << " |";
	md << "\n|---|";
	for (size_t k = 0; k < configs.size(); ++k) md << "---|";
	md << "\n";
	std::vector<int> passed(configs.size(), 0);
	for (size_t ci = 0; ci < cases.size(); ++ci)
	{
		md << "| " << cases[ci]->name << " (" << cases[ci]->group << ", expected " << figureText(results[ci][0].verdict.expected) << " "
		   << results[ci][0].verdict.unit << ") |";
		for (size_t k = 0; k < configs.size(); ++k)
		{
			const Result& r = results[ci][k];
			if (r.skipped)
				md << " skipped |";
			else
				md << " " << (r.verdict.pass ? "PASS" : "FAIL") << " " << figureText(r.verdict.figure) << " |";
			passed[k] += (!r.skipped && r.verdict.pass) ? 1 : 0;
		}
		md << "\n";
	}
	md << "| **passed** |";
	for (size_t k = 0; k < configs.size(); ++k) md << " " << passed[k] << "/" << cases.size() << " |";
	md << "\n";
	if (grid)  // the grid's three statements apart
	{
		std::vector<std::string> groups;
		for (const truth::TruthCase* c : cases)
			if (std::find(groups.begin(), groups.end(), c->group) == groups.end()) groups.push_back(c->group);
		for (const std::string& group : groups)
		{
			md << "| **passed, " << group << "** |";
			for (size_t k = 0; k < configs.size(); ++k)
			{
				int n = 0, held = 0;
				for (size_t ci = 0; ci < cases.size(); ++ci)
				{
					if (cases[ci]->group != group) continue;
					++n;
					held += (!results[ci][k].skipped && results[ci][k].verdict.pass) ? 1 : 0;
				}
				md << " " << held << "/" << n << " |";
			}
			md << "\n";
		}
	}
	md << "\n";
	for (const truth::TruthCase* c : cases) md << "- **" << c->name << "** (" << c->group << "): " << c->statement << "\n";
	md << "\nbsp_truth: " << cases.size() << " cases x " << configs.size() << " configurations in " << figureText(totalSeconds) << " s; CSV: "
	   << csvPath << "\n";
	if (mdPath.empty())
		std::cout << md.str();
	else
	{
		std::ofstream out(mdPath);
		out << md.str();
		std::cerr << "wrote " << mdPath << "\n";
	}
	std::cerr << "wrote " << csvPath << " (" << figureText(totalSeconds) << " s)\n";
	return 0;
}
