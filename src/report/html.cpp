#include "report/html.hpp"
#include "expr/memory.hpp"

#include <cstdlib>
#include <fstream>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <utility>

#ifndef TACKLE_KATEX_DIR
#define TACKLE_KATEX_DIR "/usr/share/javascript/katex"
#endif

namespace tackle {

namespace {

std::string read_asset(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw SetupError("HTML needs KaTeX, and " + path +
                     " cannot be read (install Debian's libjs-katex, or set TACKLE_KATEX_DIR to KaTeX's directory)");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string base64(const std::string& in) {
  static const char* const digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < in.size(); i += 3) {
    const unsigned v = static_cast<unsigned char>(in[i]) << 16 | static_cast<unsigned char>(in[i + 1]) << 8 |
                       static_cast<unsigned char>(in[i + 2]);
    for (int k = 18; k >= 0; k -= 6) out += digits[(v >> k) & 63];
  }
  if (i < in.size()) {
    unsigned v = static_cast<unsigned char>(in[i]) << 16;
    if (i + 1 < in.size()) v |= static_cast<unsigned char>(in[i + 1]) << 8;
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += i + 1 < in.size() ? digits[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

// KaTeX's style with each font's woff2 as a data: URL (the woff and ttf fallbacks dropped:
// every browser that runs KaTeX reads woff2).
std::string inlined_css(const std::string& dir) {
  const std::string css = read_asset(dir + "/katex.min.css");
  std::string out;
  std::size_t from = 0;
  for (std::size_t at; (at = css.find("src:", from)) != std::string::npos;) {
    const std::size_t end = css.find_first_of(";}", at);
    if (end == std::string::npos) break;
    const std::string sources = css.substr(at, end - at);
    const std::size_t open = sources.find("url(fonts/"), close = sources.find(')', open);
    out += css.substr(from, at - from);
    const std::string file =
        open == std::string::npos || close == std::string::npos ? "" : sources.substr(open + 4, close - open - 4);
    if (file.size() > 6 && file.compare(file.size() - 6, 6, ".woff2") == 0)
      out += "src:url(data:font/woff2;base64," + base64(read_asset(dir + "/" + file)) + ") format('woff2')";
    else
      out += sources;
    from = end;
  }
  return out + css.substr(from);
}

struct Assets {
  std::string css, js;
};

const Assets& assets() {
  static std::once_flag once;
  static Assets a;
  static std::string error;
  std::call_once(once, [] {
    const char* env = std::getenv("TACKLE_KATEX_DIR");
    const std::string dir = env && *env ? env : TACKLE_KATEX_DIR;
    try {
      a.css = inlined_css(dir);
      a.js = read_asset(dir + "/katex.min.js");
    } catch (const SetupError& e) {
      error = e.what();
    }
  });
  if (!error.empty()) throw SetupError(error);
  return a;
}

// The page's own style, then its content's (a hosted fragment's too, scoped to it).
const char* const page_style =
    R"(body{font-family:"Latin Modern Roman","CMU Serif",Georgia,serif;max-width:52em;margin:2em auto;padding:0 1em;line-height:1.45;color:#111}
h1{font-size:1.6em}h2{font-size:1.25em;margin-top:1.6em;border-bottom:1px solid #ccc}
)";
const char* const style =
    R"(.eq{display:flex;align-items:center;gap:1em;margin:.5em 0}.eq .math{flex:1;text-align:center}
.eq .tag{color:#555;font-size:.9em;white-space:nowrap}
figure{text-align:center;margin:1em 0;break-inside:avoid;page-break-inside:avoid}figure svg{max-width:100%;height:auto}figcaption{font-size:.9em;color:#444}
.katex-error{color:#b00;border-bottom:1px dotted #b00}
table.parameters{border-collapse:collapse;margin:.8em 0}table.parameters th,table.parameters td{padding:.15em .8em;border-bottom:1px solid #ddd;text-align:left}
table.parameters td.number{text-align:right;font-variant-numeric:tabular-nums}
)";

const char* const render = R"(document.addEventListener("DOMContentLoaded",function(){
for(const el of document.querySelectorAll(".math")){
katex.render(el.textContent,el,{displayMode:el.classList.contains("display"),throwOnError:false});}
document.body.setAttribute("data-math-rendered","true");});
)";

}  // namespace

std::string html_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

namespace {
// The hosted fragment being written on this thread, if any.
const HostedHtml*& hosted() { return thread_memory<struct hosted_memory, const HostedHtml*>(); }
}  // namespace

HostedHtml::HostedHtml(std::string ids) : ids_(std::move(ids)), outer_(hosted()) { hosted() = this; }
HostedHtml::~HostedHtml() { hosted() = outer_; }
const HostedHtml* HostedHtml::current() { return hosted(); }

std::string html_math(const std::string& tex, bool display) {
  const std::string open = !hosted() ? "" : display ? "\\[" : "\\(", close = !hosted() ? "" : display ? "\\]" : "\\)";
  return std::string("<span class=\"math") + (display ? " display" : "") + "\">" + open + html_escape(tex) + close +
         "</span>";
}

std::string content_style(const std::string& scope) {
  // Each rule "a,b{...}" as "scope a,scope b{...}" (the style has no nested rules).
  const std::string css = style;
  std::string out;
  for (std::size_t from = 0, open; (open = css.find('{', from)) != std::string::npos;) {
    const std::size_t close = css.find('}', open);
    std::string selectors = css.substr(from, open - from), scoped;
    for (std::size_t at = 0; at <= selectors.size();) {
      std::size_t comma = selectors.find(',', at);
      if (comma == std::string::npos) comma = selectors.size();
      std::string one = selectors.substr(at, comma - at);
      one.erase(0, one.find_first_not_of(" \n"));
      scoped += (scoped.empty() ? "" : ",") + scope + " " + one;
      at = comma + 1;
    }
    out += scoped + css.substr(open, close + 1 - open) + "\n";
    from = close + 1;
  }
  return out;
}

std::string html_page(const std::string& title, const std::string& body, const std::string& head) {
  const Assets& a = assets();
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<meta name=\"viewport\" "
         "content=\"width=device-width, initial-scale=1\">\n<title>" +
         html_escape(title) + "</title>\n<style>\n" + a.css + "\n</style>\n<style>\n" + page_style + style +
         "</style>\n<script>\n" + a.js + "\n</script>\n<script>\n" + render + "</script>\n" + head +
         "</head>\n<body>\n" + body + "</body>\n</html>\n";
}

}  // namespace tackle
