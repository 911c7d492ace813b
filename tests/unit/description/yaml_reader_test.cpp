// The YAML loader (libyaml's events into located nodes) that the description and rule
// readers share.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "description/yaml_reader.hpp"

using namespace tackle;

namespace {

struct Loaded {
  yaml::Document doc;
  std::vector<std::string> errors;
};

Loaded load(const std::string& text) {
  Diagnostics diags;
  Loaded out{yaml::load(text, "t.yaml", diags), {}};
  for (const auto& d : diags.items()) out.errors.push_back(format(d));
  return out;
}

std::string at(const yaml::Node& n) {
  const Location l = yaml::where(n, "t.yaml");
  return std::to_string(l.line) + ":" + std::to_string(l.column);
}

}  // namespace

TEST_CASE("YAML: empty values and the null words are null, quoted ones are text", "[yaml]") {
  const auto l = load("{a: , b: ~, c: null, d: Null, e: NULL, f: \"\", g: 'null', h: nil}");
  REQUIRE(l.errors.empty());
  const yaml::Node r = l.doc.root();
  for (const char* k : {"a", "b", "c", "d", "e"}) {
    INFO(k);
    CHECK(r[k].is_null());
    CHECK(r[k].defined());
  }
  CHECK(r["f"].is_scalar());
  CHECK(r["f"].text().empty());
  CHECK(r["g"].text() == "null");
  CHECK(r["h"].text() == "nil");
  CHECK(!r["z"]);
  CHECK(r["z"].type() == yaml::NodeType::Undefined);
}

TEST_CASE("YAML: a quoted scalar is located at its first character, a plain one at its start", "[yaml]") {
  const auto l = load("title: plain\nname: \"quoted\"\nother: 'single'\nlist:\n  - x\n  - {y: z}\n");
  REQUIRE(l.errors.empty());
  const yaml::Node r = l.doc.root();
  CHECK(at(r) == "1:1");
  CHECK(at(r["title"]) == "1:8");
  CHECK(at(r["name"]) == "2:8");
  CHECK(at(r["other"]) == "3:9");
  CHECK(at(r["list"]) == "5:3");
  CHECK(at(r["list"][0]) == "5:5");
  CHECK(at(r["list"][1]) == "6:5");
  CHECK(at(r["list"][1]["y"]) == "6:9");
}

TEST_CASE("YAML: a mapping keeps its entries in order, a repeated key too", "[yaml]") {
  const auto l = load("{b: 1, a: 2, b: 3}");
  REQUIRE(l.errors.empty());
  const yaml::Node r = l.doc.root();
  REQUIRE(r.size() == 3);
  std::vector<std::string> seen;
  for (const auto& kv : r) seen.push_back(kv.first.text() + "=" + kv.second.text());
  CHECK(seen == std::vector<std::string>{"b=1", "a=2", "b=3"});
  CHECK(r["b"].text() == "1");  // the first one
  Diagnostics diags;
  yaml::check_unique_keys(r, "the map", "t.yaml", diags);
  REQUIRE(diags.items().size() == 1);
  CHECK(format(diags.items()[0]) == "t.yaml:1:14: duplicate key 'b' in the map");
}

TEST_CASE("YAML: a list is walked item by item, asking a list for a key gives nothing", "[yaml]") {
  const auto l = load("[1, [2, 3], {k: v}]");
  REQUIRE(l.errors.empty());
  const yaml::Node r = l.doc.root();
  REQUIRE(r.is_sequence());
  REQUIRE(r.size() == 3);
  std::vector<yaml::NodeType> types;
  for (const auto& item : r) types.push_back(item.type());
  CHECK(types == std::vector<yaml::NodeType>{yaml::NodeType::Scalar, yaml::NodeType::Sequence, yaml::NodeType::Map});
  CHECK(!r["k"]);
  CHECK(!r[3]);
  CHECK(!r[0]["k"]);
  CHECK(!r[0][0]);
  CHECK(r[2]["k"].text() == "v");
  CHECK(r[1].text().empty());
}

TEST_CASE("YAML: an alias is the node its anchor names", "[yaml]") {
  const auto l = load("a: &p [1, 2]\nb: *p\n");
  REQUIRE(l.errors.empty());
  const yaml::Node b = l.doc.root()["b"];
  REQUIRE(b.is_sequence());
  CHECK(b.size() == 2);
  CHECK(at(b) == "1:4");  // where the anchored node is written, its anchor first
}

TEST_CASE("YAML: an alias to no anchor, or to the node it is inside, is an error", "[yaml]") {
  CHECK(load("a: *nope\n").errors ==
        std::vector<std::string>{"t.yaml:1:4: invalid YAML: the alias *nope names no anchor before it "
                                 "(expected &nope on a complete node earlier in the file)"});
  CHECK(load("a: &r [1, *r]\n").errors ==
        std::vector<std::string>{"t.yaml:1:11: invalid YAML: the alias *r names no anchor before it "
                                 "(expected &r on a complete node earlier in the file)"});
}

TEST_CASE("YAML: a syntax error is located, with what libyaml was reading", "[yaml]") {
  const auto l = load("a: [1, 2\nb: 3\n");
  CHECK(l.errors == std::vector<std::string>{"t.yaml:2:2: invalid YAML: did not find expected ',' or ']' "
                                             "(while parsing a flow sequence started at line 1, column 4)"});
  CHECK(!l.doc.root());
  CHECK(load("a: b\x01"
             "c\n")
            .errors == std::vector<std::string>{"t.yaml:1:5: invalid YAML: control characters are not allowed"});
  CHECK(load("a: b\n\xff").errors ==
        std::vector<std::string>{"t.yaml:2:1: invalid UTF-8 byte 0xFF (expected UTF-8 text)"});
}

TEST_CASE("YAML: an empty text is null, only the first document is read", "[yaml]") {
  const auto empty = load("# nothing but a comment\n");
  REQUIRE(empty.errors.empty());
  CHECK(empty.doc.root().is_null());
  CHECK(at(empty.doc.root()) == "0:0");
  const auto two = load("a: 1\n---\n[not read\n");
  REQUIRE(two.errors.empty());
  CHECK(two.doc.root()["a"].text() == "1");
}

TEST_CASE("YAML: deep nesting is loaded without recursion", "[yaml]") {
  const int depth = 100000;
  const auto l = load(std::string(depth, '[') + std::string(depth, ']'));
  REQUIRE(l.errors.empty());
  yaml::Node n = l.doc.root();
  int levels = 0;
  while (n.is_sequence() && n.size() == 1) {
    n = n[0];
    ++levels;
  }
  CHECK(levels == depth - 1);
  CHECK(n.is_sequence());
  CHECK(n.size() == 0);
}

TEST_CASE("YAML: aliases may not repeat more nodes than the file has, or 10000", "[yaml]") {
  // Each alias is the node it names, so a reader walks that node once per alias: four
  // levels of ten aliases each are 10^4 walks of a ten-item list from a 200-byte file.
  std::string text = "a: &a [x, x, x, x, x, x, x, x, x, x]\n";
  for (const char* level : {"b", "c", "d", "e"}) {
    const char below = static_cast<char>(level[0] - 1);
    text += std::string(level) + ": &" + level + " [";
    for (int i = 0; i < 10; ++i) text += std::string(i ? ", *" : "*") + below;
    text += "]\n";
  }
  CHECK(load(text).errors ==
        std::vector<std::string>{"t.yaml:4:36: invalid YAML: with the alias *c, aliases repeat 10108 nodes "
                                 "(expected at most 10000, or as many as the file itself has)"});
  // The same aliases, fewer of them: 10 + 10 * 11 + ... stays under the limit and is read.
  const auto small = load(
      "a: &a [x, x, x, x, x, x, x, x, x, x]\nb: &b [*a, *a, *a, *a, *a, *a, *a, *a, *a, *a]\n"
      "c: [*b, *b, *b, *b, *b, *b, *b, *b, *b, *b]\n");
  REQUIRE(small.errors.empty());
  CHECK(small.doc.root()["c"][9][9][9].text() == "x");
}
