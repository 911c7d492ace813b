#include "crosscheck/expr.hpp"

#include <cctype>
#include <cstdlib>
#include <numbers>

namespace crosscheck {
namespace {

using NodeP = std::shared_ptr<const Expr::Node>;

NodeP make(Expr::Node::Kind k, NodeP l = nullptr, NodeP r = nullptr) {
  auto n = std::make_shared<Expr::Node>();
  n->kind = k;
  n->l = std::move(l);
  n->r = std::move(r);
  return n;
}
NodeP number(double v) {
  auto n = std::make_shared<Expr::Node>();
  n->kind = Expr::Node::num;
  n->value = v;
  return n;
}

class Parser {
 public:
  Parser(const std::string& t, const std::function<int(const std::string&)>& slot) : s_(t), slot_(slot) {}
  NodeP parse() {
    NodeP n = sum();
    skip();
    if (i_ != s_.size()) fail("unexpected '" + s_.substr(i_, 1) + "'");
    return n;
  }

 private:
  const std::string& s_;
  const std::function<int(const std::string&)>& slot_;
  std::size_t i_ = 0;

  [[noreturn]] void fail(const std::string& why) const {
    throw std::runtime_error("cannot read expression '" + s_ + "': " + why);
  }
  void skip() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool eat(char c) {
    skip();
    if (i_ < s_.size() && s_[i_] == c) {
      ++i_;
      return true;
    }
    return false;
  }
  NodeP sum() {
    NodeP n = product();
    for (;;) {
      if (eat('+'))
        n = make(Expr::Node::add, n, product());
      else if (eat('-'))
        n = make(Expr::Node::sub, n, product());
      else
        return n;
    }
  }
  NodeP product() {
    NodeP n = unary();
    for (;;) {
      if (eat('*'))
        n = make(Expr::Node::mul, n, unary());
      else if (eat('/'))
        n = make(Expr::Node::div, n, unary());
      else
        return n;
    }
  }
  NodeP unary() {
    if (eat('-')) return make(Expr::Node::neg, unary());
    if (eat('+')) return unary();
    return power();
  }
  NodeP power() {
    NodeP base = primary();
    if (!eat('^')) return base;
    NodeP e = unary();
    // An integer exponent multiplies (a negative base stays real).
    const Expr::Node* en = e.get();
    bool negated = false;
    if (en->kind == Expr::Node::neg) {
      negated = true;
      en = en->l.get();
    }
    if (en->kind == Expr::Node::num && en->value == static_cast<int>(en->value) && std::abs(en->value) <= 64) {
      auto n = std::make_shared<Expr::Node>();
      n->kind = Expr::Node::ipow;
      n->l = base;
      n->exponent = static_cast<int>(en->value) * (negated ? -1 : 1);
      return n;
    }
    return make(Expr::Node::pow, base, e);
  }
  NodeP primary() {
    skip();
    if (i_ >= s_.size()) fail("it ends too early");
    char c = s_[i_];
    if (c == '(') {
      ++i_;
      NodeP n = sum();
      if (!eat(')')) fail("expected ')'");
      return n;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      const char* start = s_.c_str() + i_;
      char* end = nullptr;
      double v = std::strtod(start, &end);
      if (end == start) fail("bad number");
      i_ += static_cast<std::size_t>(end - start);
      return number(v);
    }
    if (std::isalpha(static_cast<unsigned char>(c))) {
      std::size_t b = i_;
      while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_')) ++i_;
      std::string name = s_.substr(b, i_ - b);
      skip();
      if (i_ < s_.size() && s_[i_] == '(') {
        if (name == "dot" || name == "ddot") {
          ++i_;
          skip();
          std::size_t a = i_;
          while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_')) ++i_;
          std::string inner = s_.substr(a, i_ - a);
          if (!eat(')')) fail("expected ')' after " + name + "(" + inner);
          return variable(name + "(" + inner + ")");
        }
        ++i_;
        NodeP arg = sum();
        if (!eat(')')) fail("expected ')'");
        static const std::pair<const char*, Expr::Node::Kind> functions[] = {
            {"sqrt", Expr::Node::fsqrt}, {"abs", Expr::Node::fabs}, {"sin", Expr::Node::fsin},
            {"cos", Expr::Node::fcos},   {"tan", Expr::Node::ftan}, {"exp", Expr::Node::fexp},
            {"log", Expr::Node::flog}};
        for (const auto& [fname, kind] : functions)
          if (name == fname) return make(kind, arg);
        fail("unknown function '" + name + "'");
      }
      if (name == "pi" && slot_(name) < 0) return number(std::numbers::pi);
      return variable(name);
    }
    fail(std::string("unexpected '") + c + "'");
  }
  NodeP variable(const std::string& name) {
    int k = slot_(name);
    if (k < 0) fail("unknown name '" + name + "'");
    auto n = std::make_shared<Expr::Node>();
    n->kind = Expr::Node::var;
    n->slot = k;
    return n;
  }
};

bool uses_slot(const Expr::Node* n, int slot) {
  if (!n) return false;
  if (n->kind == Expr::Node::var) return n->slot == slot;
  return uses_slot(n->l.get(), slot) || uses_slot(n->r.get(), slot);
}

}  // namespace

Expr Expr::compile(const std::string& text, const std::function<int(const std::string&)>& slot) {
  Expr e;
  e.root_ = Parser(text, slot).parse();
  return e;
}

Expr Expr::constant(double v) {
  Expr e;
  e.root_ = number(v);
  return e;
}

bool Expr::uses(int slot) const { return uses_slot(root_.get(), slot); }

std::vector<Expr> Expr::divisors() const {
  std::vector<Expr> out;
  const std::function<void(const std::shared_ptr<const Node>&)> walk = [&](const std::shared_ptr<const Node>& n) {
    if (!n) return;
    if (n->kind == Node::div || (n->kind == Node::ipow && n->exponent < 0)) {
      Expr d;
      d.root_ = n->kind == Node::div ? n->r : n->l;
      out.push_back(d);
    }
    walk(n->l);
    walk(n->r);
  };
  walk(root_);
  return out;
}

double Expr::magnitude(const std::vector<double>& vars) const {
  const std::function<double(const Node*)> size = [&](const Node* n) -> double {
    switch (n->kind) {
      case Node::neg: return size(n->l.get());
      case Node::add:
      case Node::sub: return size(n->l.get()) + size(n->r.get());
      case Node::mul: return size(n->l.get()) * size(n->r.get());
      case Node::div: return size(n->l.get()) / std::abs(eval_node<double>(n->r.get(), vars));
      case Node::ipow:
        if (n->exponent > 0) return std::pow(size(n->l.get()), n->exponent);
        return std::abs(eval_node<double>(n, vars));
      default: return std::abs(eval_node<double>(n, vars));
    }
  };
  return size(root_.get());
}

std::optional<double> evaluate_text(const std::string& text, const std::map<std::string, double>& values,
                                    const std::function<bool(const std::string&)>& usable) {
  std::vector<double> vars;
  bool known = true;
  try {
    const Expr e = Expr::compile(text, [&](const std::string& n) {
      if (n == "pi" && !values.count(n)) return -1;
      auto it = values.find(n);
      if (it == values.end() || (usable && !usable(n))) known = false;
      vars.push_back(it == values.end() ? 0.0 : it->second);
      return static_cast<int>(vars.size()) - 1;
    });
    if (!known) return std::nullopt;
    return e.eval(vars);
  } catch (const std::runtime_error&) {
    return std::nullopt;
  }
}

}  // namespace crosscheck
