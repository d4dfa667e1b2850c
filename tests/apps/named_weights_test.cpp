// Unit tests of named_weights.h: which example a --weight key names (file
// stem, whole recorded source, 1-based index) and the errors for keys that
// name none, several, or one twice. The command-line runs are in
// weight_options_test.cpp.

#include "named_weights.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tetblend/core/error.h"

namespace tetblend::cli {
namespace {

// Two stems "frame001" in different folders, a stem that spells an index
// ("2"), and an absolute source.
const std::vector<std::string> kSources = {"poses/frame000.obj", "poses/frame001.obj",
                                           "other/frame001.obj", "2.obj", "/abs/x.ply"};

/// The message of the InputError `f` throws ("" and a failure if none).
template <typename F>
std::string inputError(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

std::string findError(const std::string& key, const std::string& modelPath = "m.tbm") {
  return inputError([&] { findExample(key, kSources, "--weight " + key + "=1", modelPath); });
}

TEST(FindExample, ByStemWholeSourceOrIndex) {
  EXPECT_EQ(findExample("frame000", kSources, "w", "m.tbm"), 0u);
  EXPECT_EQ(findExample("x", kSources, "w", "m.tbm"), 4u);
  EXPECT_EQ(findExample("/abs/x.ply", kSources, "w", "m.tbm"), 4u);
  // A whole source wins over the two examples of its stem.
  EXPECT_EQ(findExample("other/frame001.obj", kSources, "w", "m.tbm"), 2u);
  EXPECT_EQ(findExample("1", kSources, "w", "m.tbm"), 0u);
  EXPECT_EQ(findExample("4", kSources, "w", "m.tbm"), 3u);
  EXPECT_EQ(findExample("5", kSources, "w", "m.tbm"), 4u);
}

TEST(FindExample, UnknownNameListsSomeNamesAndHowToSeeAll) {
  const std::string e = findError("frame999");
  EXPECT_EQ(e.rfind("--weight frame999=1: no example is named 'frame999'", 0), 0u) << e;
  EXPECT_NE(e.find("frame000, frame001, frame001, 2, x (5 in all"), std::string::npos) << e;
  EXPECT_NE(e.find("index 1..5"), std::string::npos) << e;
  EXPECT_NE(e.find("'tetblend inspect m.tbm' lists them all"), std::string::npos) << e;
  // Examples given on the command line: no model to inspect.
  EXPECT_EQ(findError("frame999", "").find("inspect"), std::string::npos);
  // More examples than are quoted: the list ends in "...".
  std::vector<std::string> many;
  for (int k = 0; k < 48; ++k) many.push_back("f" + std::to_string(k) + ".obj");
  const std::string m = inputError([&] { findExample("g", many, "w", "m.tbm"); });
  EXPECT_NE(m.find("f0, f1, f2, f3, f4, ... (48 in all"), std::string::npos) << m;
}

TEST(FindExample, StemOfSeveralExamplesAsksForTheIndex) {
  const std::string e = findError("frame001");
  EXPECT_NE(e.find("names 2 examples, 2 (poses/frame001.obj), 3 (other/frame001.obj)"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("give the index"), std::string::npos) << e;
}

TEST(FindExample, IndexOutOfRangeGivesTheRange) {
  for (const std::string key : {"0", "6", "99999999999999999999999999"}) {
    const std::string e = findError(key);
    EXPECT_NE(e.find("there is no example " + key + "; the examples are numbered 1..5"),
              std::string::npos)
        << e;
  }
}

// "2" is example 2's index and example 4's stem (2.obj): refused, since files
// numbered like 1.obj, 2.obj... are easily prepared in another order.
TEST(FindExample, IndexThatNamesAnotherExampleIsRefused) {
  const std::string e = findError("2");
  EXPECT_NE(e.find("'2' is the index of example 2 (poses/frame001.obj) and also names example 4 "
                   "(2.obj)"),
            std::string::npos)
      << e;
  // An index that names itself, or a number beyond the indices, is a name.
  EXPECT_EQ(findExample("1", {"1.obj", "b.obj"}, "w", ""), 0u);
  EXPECT_EQ(findExample("7", {"a.obj", "7.obj"}, "w", ""), 1u);
}

TEST(ExampleWeights, UnnamedExamplesGetZeroAndAnExampleNamedTwiceIsRefused) {
  EXPECT_EQ(exampleWeights({{"frame000", 0.5, "a"}, {"5", -0.25, "b"}}, kSources, "m.tbm"),
            (std::vector<double>{0.5, 0, 0, 0, -0.25}));
  EXPECT_EQ(exampleWeights({}, kSources, "m.tbm"), std::vector<double>(5, 0.0));
  const std::string e = inputError([] {
    exampleWeights({{"x", 1, "--weight x=1"}, {"5", 2, "--weight 5=2"}}, kSources, "");
  });
  EXPECT_EQ(e, "--weight 5=2: example 5 (/abs/x.ply) already has a weight, from --weight x=1");
}

TEST(ParseExampleWeight, NameOrIndexThenAFiniteValue) {
  const ExampleWeight w = parseExampleWeight("a=b= 0.5", "--weight a=b= 0.5");
  EXPECT_EQ(w.example, "a=b");  // split at the last '='
  EXPECT_EQ(w.weight, 0.5);
  EXPECT_EQ(w.where, "--weight a=b= 0.5");
  for (const std::string text : {"a", "=0.5", "a=", "a=nan", "a=inf", "a=1e999", "a=0.5x"}) {
    const std::string e = inputError([&] { parseExampleWeight(text, "--weight " + text); });
    EXPECT_EQ(e.rfind("--weight " + text + ": ", 0), 0u) << e;
  }
}

}  // namespace
}  // namespace tetblend::cli
