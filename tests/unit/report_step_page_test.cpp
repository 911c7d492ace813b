// The page to try the step checker (report/step_page): what it shows of the problem, what its
// form offers, what it may connect to, and that no text from the description reaches it as HTML.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "report/step_page.hpp"
#include "support/helpers.hpp"

using namespace tackle;

namespace {

// The form's data: the JSON in <script id="tackle-problem">.
nlohmann::json config_of(const std::string& page) {
  const std::string open = "<script type=\"application/json\" id=\"tackle-problem\">";
  const auto from = page.find(open);
  REQUIRE(from != std::string::npos);
  const auto to = page.find("</script>", from);
  return nlohmann::json::parse(page.substr(from + open.size(), to - from - open.size()));
}

std::string page_of(const std::string& example, const std::string& endpoint = "") {
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/" + example, test::rules());
  return step_page(explain(*a), a->model, endpoint);
}

// A block pushed along a smooth floor by F, its title and statement left to each test.
const char* const pushed_block = R"(axes: [x]
parameters: {F: {value: 10, unit: N}, m: {value: 2, unit: kg}}
bodies: {A: {mass: m, position: x}}
loads: [{on: A, force: F}]
find: [ddot(x)]
)";

}  // namespace

TEST_CASE("Step page: sample 12.3's statement with its numbers, its sketch, its points, bodies and unknowns",
          "[page]") {
  const std::string page = page_of("sample-12.3-two-mass-pulley.yaml");
  CHECK(page.find("<h1>Sample 12.3: a two-mass pulley system</h1>") != std::string::npos);
  // The statement's {F} filled in as the sheet does (130 N, in math for KaTeX).
  CHECK(page.find("Blocks A and B") != std::string::npos);
  CHECK(page.find("130\\,\\mathrm{N}") != std::string::npos);
  CHECK(page.find("<svg") != std::string::npos);  // the mechanism's sketch
  const auto c = config_of(page);
  CHECK(c["dims"] == 1);
  CHECK(c["axes"] == nlohmann::json::array({"x"}));
  // The points described, and each body's center of mass (its name).
  CHECK(c["points"] == nlohmann::json::array({"A", "B", "C", "pA", "pB"}));
  CHECK(c["bodies"] == nlohmann::json::array({"A", "B"}));
  std::vector<std::string> unknowns;
  for (const auto& u : c["unknowns"]) unknowns.push_back(u["name"]);
  CHECK(unknowns == std::vector<std::string>{"T", "ddot(x_A)", "ddot(x_B)"});
  CHECK(c["endpoint"] == "");
  // The names a student types, the positions among them (for the length sum).
  for (const char* name : {"<code>F</code>", "<code>m_A</code>", "<code>x_A</code>", "<code>ddot(x_B)</code>"})
    CHECK(page.find(name) != std::string::npos);
  // It connects to its own origin only, and loads nothing from elsewhere.
  CHECK(page.find("connect-src 'self';") != std::string::npos);
  for (const char* elsewhere : {"src=\"http", "href=\"http", "url(http", "src=\"//", "href=\"//", "url(//"})
    CHECK(page.find(elsewhere) == std::string::npos);
}

TEST_CASE("Step page: its hints are the problem's own, never another example's", "[page]") {
  // Sample 12.3 by hand: its first balance is LMB A (x), 2T - F = m_A ddot(x_A), whose forces
  // are the student's to find; its parameters F, m_A, m_B; its unknown force T (N).
  const auto c = config_of(page_of("sample-12.3-two-mass-pulley.yaml"));
  CHECK(c["hints"] ==
        nlohmann::json::parse(
            R"J({"equation": "LMB A (x): ... = m_A*ddot(x_A)", "answer": "in F, m_A, m_B", "force": "T"})J"));
  CHECK(c["unknowns"][0]["unit"] == "N");
  CHECK(c["unknowns"][1]["unit"] == "m/s^2");
  // The incline: its first balance, LMB A (x), has the incline's projection on its inertial
  // side (m_A ddot(s) cos(theta)), which the hint keeps back; sample 12.3's names appear nowhere.
  const std::string incline = page_of("incline-and-hanging-block.yaml");
  CHECK(config_of(incline)["hints"] ==
        nlohmann::json::parse(
            R"J({"equation": "LMB A (x): ... = ...", "answer": "in m_A, m_B, g, theta, ...", "force": "N_A"})J"));
  for (const char* other : {"x_A", "x_B", "2*F", "3*x_B"}) CHECK(incline.find(other) == std::string::npos);
  CHECK(incline.find("<code>dot(s)</code> and <code>ddot(s)</code> for its rate and acceleration") !=
        std::string::npos);
  // Sample 12.2 needs no balance (its string alone): the hint is its constraint's, with no force.
  CHECK(config_of(page_of("sample-12.2-pulley-kinematics.yaml"))["hints"] ==
        nlohmann::json::parse(R"J({"equation": "string s: acceleration: ... = 0", "answer": "in d", "force": ""})J"));
  // A problem with no quantity held constant is not offered one.
  const auto a = test::run_text(std::string("title: pushed\n") + pushed_block);
  const std::string pushed = step_page(explain(*a), a->model);
  CHECK(pushed.find("an equation (a balance), a final answer") != std::string::npos);
  CHECK(pushed.find("<code>... = const</code>") == std::string::npos);
}

TEST_CASE("Step page: a 2-D problem's form asks for angles, an endpoint elsewhere is the one other source", "[page]") {
  const std::string page = page_of("sample-12.7-suitcase.yaml", "http://127.0.0.1:8123/tackle/");
  const auto c = config_of(page);
  CHECK(c["dims"] == 2);
  CHECK(c["endpoint"] == "http://127.0.0.1:8123/tackle/");
  CHECK(page.find("connect-src 'self' http://127.0.0.1:8123;") != std::string::npos);
}

TEST_CASE("Step page: no text from the description reaches the page as HTML", "[page]") {
  const auto a = test::run_text(R"(title: "A <b>bold</b> title </script>"
statement: "Pull with {F}. <script>alert(1)</script> <img src=x onerror=alert(2)> & $a < b$"
)" + std::string(pushed_block));
  const std::string page = step_page(explain(*a), a->model);
  CHECK(page.find("<script>alert") == std::string::npos);
  CHECK(page.find("<img src=x") == std::string::npos);
  CHECK(page.find("<b>bold") == std::string::npos);
  CHECK(page.find("&lt;script&gt;alert(1)&lt;/script&gt;") != std::string::npos);
  CHECK(page.find("A &lt;b&gt;bold&lt;/b&gt; title") != std::string::npos);
  // The title in the form's JSON cannot end its script element early.
  CHECK(page.find("title </script>") == std::string::npos);
  // Every <script> opened is one of the page's own four (KaTeX, its typesetting, the form's,
  // the form's data): nothing else.
  std::size_t scripts = 0;
  for (std::size_t at = 0; (at = page.find("<script", at)) != std::string::npos; ++at) ++scripts;
  CHECK(scripts == 4);
}

TEST_CASE("Step page: an endpoint that could break out of the page's policy is refused", "[page]") {
  CHECK(endpoint_problem("").empty());
  CHECK(endpoint_problem("/tackle").empty());
  CHECK(endpoint_problem("https://grader.example.edu/tackle").empty());
  CHECK_FALSE(endpoint_problem("/a; script-src *").empty());
  CHECK_FALSE(endpoint_problem("/a\"><script>").empty());
  CHECK_FALSE(endpoint_problem("javascript://x").empty());
  CHECK(endpoint_problem("javascript:alert(1)") == "is a URL that is not http or https");
  CHECK(endpoint_problem("data:text/html") == "is a URL that is not http or https");
  CHECK(endpoint_problem("http://127.0.0.1:8000/t").empty());
  CHECK(endpoint_problem("tackle/v1:beta").empty());
  CHECK_FALSE(endpoint_problem("/a?x=1").empty());
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.3-two-mass-pulley.yaml", test::rules());
  CHECK_THROWS_AS(step_page(explain(*a), a->model, "'self' *"), std::invalid_argument);
}
