#include "model/load_origin.hpp"

namespace tackle {

using Kind = LoadOrigin::Kind;

LoadOrigin weight_origin(const std::string& body) {
  LoadOrigin o;
  o.kind = Kind::weight;
  o.body = body;
  return o;
}

LoadOrigin connection_origin(const std::string& label, const std::string& rule) {
  LoadOrigin o;
  o.connection = label;
  o.rule = rule;
  return o;
}

LoadOrigin strand_origin(const LoadOrigin& connection, const std::string& strand, const std::string& point) {
  LoadOrigin o = connection_origin(connection.connection, connection.rule);
  o.kind = Kind::strand;
  o.strand = strand;
  o.point = point;
  return o;
}

LoadOrigin length_sum_origin(const LoadOrigin& connection, const std::string& body) {
  LoadOrigin o = connection_origin(connection.connection, connection.rule);
  o.kind = Kind::length_sum;
  o.body = body;
  return o;
}

std::string sentence(const LoadOrigin& o) {
  switch (o.kind) {
    case Kind::weight: return "gravity on " + o.body;
    case Kind::strand: return o.connection + ": strand " + o.strand + " at " + o.point;
    case Kind::length_sum: return o.connection + " (from its length sum) on " + o.body;
    default: return o.connection;
  }
}

std::string force_key(const LoadOrigin& o) {
  return o.kind == Kind::strand ? o.connection + ": strand " + o.strand : sentence(o);
}

std::string force_phrase(const LoadOrigin& o) {
  switch (o.kind) {
    case Kind::weight: return "the weight of " + o.body;
    case Kind::strand: return (o.rule == "string" ? "a strand of " : "the force of ") + o.connection + " at " + o.point;
    case Kind::applied: return "the " + o.connection;
    case Kind::sliding: return "the force of the sliding contact at " + o.point;
    default: return generic_phrase(sentence(o));
  }
}

std::string couple_phrase(const LoadOrigin& o) {
  return o.rule == "couple" ? "the " + sentence(o) : "the couple of the " + sentence(o);
}

std::string generic_phrase(const std::string& sentence) { return "the force of the " + sentence; }

}  // namespace tackle
