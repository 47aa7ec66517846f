// `illum exercise`: every answer of the key is what `illum eval` answers for the command the key
// quotes, the Gouraud point is the weighted sum of its vertices, and a seed always gives the same sheet.
#include "cli_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <regex>
#include <sstream>

namespace {

using illum::test::runIllum;

std::vector<double> numbers(const std::string& text) {
  std::vector<double> values;
  std::istringstream in(text);
  for (double v; in >> v;) values.push_back(v);
  return values;
}

TEST(Exercise, EveryAnswerIsWhatEvalAnswers) {
  int checked = 0;
  for (const char* seed : {"1", "7", "42", "2026"}) {
    const auto sheet = runIllum(std::string("exercise --seed ") + seed + " --count 15");
    ASSERT_EQ(sheet.exitCode, 0) << sheet.err;
    std::istringstream lines(sheet.out);
    std::string line, command;
    nlohmann::json report;
    const std::regex check(R"(^Check with `illum eval (.*)`:$)"), answer(R"(^- (\w+) = ([-0-9. ]+)$)");
    std::smatch m;
    while (std::getline(lines, line)) {
      if (std::regex_match(line, m, check)) {
        command = m[1];
        const auto eval = runIllum("eval " + command + " --json");
        ASSERT_EQ(eval.exitCode, 0) << command << "\n" << eval.err;
        report = nlohmann::json::parse(eval.out);
        continue;
      }
      if (line.empty()) command.clear();
      if (command.empty() || !std::regex_match(line, m, answer)) continue;
      const std::vector<double> stated = numbers(m[2]);
      const nlohmann::json& value = report.at(std::string(m[1]));
      const std::vector<double> expected = value.is_array() ? value.get<std::vector<double>>() : std::vector<double>{value.get<double>()};
      ASSERT_EQ(stated.size(), expected.size()) << line;
      for (std::size_t i = 0; i < stated.size(); ++i) EXPECT_NEAR(stated[i], expected[i], 5e-5) << "seed " << seed << ": " << line;
      ++checked;
    }
  }
  EXPECT_GE(checked, 150);
}

TEST(Exercise, TheGouraudPointIsTheWeightedSumOfItsVertices) {
  const auto sheet = runIllum("exercise --seed 3 --count 6 --kinds gouraud");
  ASSERT_EQ(sheet.exitCode, 0) << sheet.err;
  const std::regex weights(R"(barycentric weights \(([0-9.]+), ([0-9.]+), ([0-9.]+)\))");
  const std::regex vertex(R"(^- vertex \d: diffuse = k_d · cos \d+° = ([-0-9. ]+)$)");
  const std::regex point(R"(^- Gouraud interpolates .* = ([-0-9. ]+)$)");
  std::vector<std::vector<double>> allWeights;
  for (std::sregex_iterator it(sheet.out.begin(), sheet.out.end(), weights), end; it != end; ++it)
    allWeights.push_back({std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3])});
  ASSERT_EQ(allWeights.size(), 6u);
  std::istringstream lines(sheet.out.substr(sheet.out.find("# Answers")));
  std::vector<std::vector<double>> vertices;
  std::size_t problem = 0;
  std::smatch m;
  for (std::string line; std::getline(lines, line);) {
    if (std::regex_match(line, m, vertex)) vertices.push_back(numbers(m[1]));
    if (!std::regex_match(line, m, point)) continue;
    ASSERT_EQ(vertices.size(), 3u);
    const std::vector<double> p = numbers(m[1]);
    const std::vector<double>& w = allWeights[problem++];
    EXPECT_NEAR(w[0] + w[1] + w[2], 1, 1e-9);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(p[c], w[0] * vertices[0][c] + w[1] * vertices[1][c] + w[2] * vertices[2][c], 2e-4) << line;
    vertices.clear();
  }
  EXPECT_EQ(problem, 6u);
}

TEST(Exercise, ASeedGivesTheSameSheetAndAnotherSeedAnother) {
  const auto a = runIllum("exercise --seed 11 --count 10"), b = runIllum("exercise --seed 11 --count 10");
  const auto c = runIllum("exercise --seed 12 --count 10");
  EXPECT_EQ(a.out, b.out);
  EXPECT_NE(a.out, c.out);
  const auto problems = runIllum("exercise --seed 11 --count 10 --no-answers");
  EXPECT_EQ(problems.out.find("# Answers"), std::string::npos);
  EXPECT_EQ(a.out.rfind(problems.out, 0), 0u) << "the problems are the same with and without the key";
}

TEST(Exercise, HtmlIsTheSameSheet) {
  illum::test::TempDir dir;
  const std::string out = (dir / "sheet.html").string();
  const auto r = runIllum("exercise --seed 5 --count 5 -o " + out);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string page = illum::test::slurp(out);
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(page.find("<h1>Answers</h1>"), std::string::npos);
  EXPECT_NE(page.find("<code>illum eval --model"), std::string::npos);
  const auto md = runIllum("exercise --seed 5 --count 5");
  const std::size_t title = md.out.find("## 1. ");
  const std::string first = md.out.substr(title + 6, md.out.find('\n', title) - title - 6);
  EXPECT_NE(page.find("<h2>1. " + first + "</h2>"), std::string::npos) << first;
}

TEST(Exercise, AnUnknownKindNamesTheClosest) {
  const auto r = runIllum("exercise --kinds atenuation");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("did you mean attenuation?"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

}  // namespace
