// Where a load comes from, as data: gravity on a body, a connection's own load, a strand of a
// connection's path, a length sum's force on a body. The sentence the reports print, the key
// that groups a connection's strands and the phrase a student reads are made from it.
#pragma once

#include <string>

namespace tackle {

/// The origin of a load (Load::origin).
struct LoadOrigin {
  enum class Kind {
    weight,      // gravity on `body`: "gravity on A"
    connection,  // a connection's own load: "pin at O"
    applied,     // a force connection's (rule force): "force on A"
    sliding,     // a sliding contact's, its label made of its point: "sliding at P"
    strand,      // a strand of a connection's path, at one end: "string s: strand pB-C at pB"
    length_sum,  // a length sum's force on `body`: "string s (from its length sum) on A"
  };
  Kind kind = Kind::connection;
  std::string connection;  // the connection's label ("string s", "force on A"); empty for a weight
  std::string rule;        // the connection's rule type ("string", "couple"); empty for a weight
  std::string body;        // weight, length_sum: the body's name
  std::string strand;      // strand: its ends ("pB-C")
  std::string point;       // strand: the end it acts at; sliding: the contact's point
};

/// The weight of body `body`.
[[nodiscard]] LoadOrigin weight_origin(const std::string& body);
/// A load of the connection labelled `label`, of rule type `rule`, itself (kind connection).
[[nodiscard]] LoadOrigin connection_origin(const std::string& label, const std::string& rule);
/// A connection's load along its strand `strand` ("pB-C"), at its end `point`.
[[nodiscard]] LoadOrigin strand_origin(const LoadOrigin& connection, const std::string& strand,
                                       const std::string& point);
/// A connection's force from its length sum on body `body`.
[[nodiscard]] LoadOrigin length_sum_origin(const LoadOrigin& connection, const std::string& body);

/// The sentence the reports print: "gravity on A", "string s: strand pB-C at pB", "force on A".
[[nodiscard]] std::string sentence(const LoadOrigin& o);
/// The one connection or strand a load comes from, whichever body it acts on: "string s:
/// strand pB-C" for a strand; the sentence otherwise (a length sum's keeps its body: "string s
/// (from its length sum) on A").
[[nodiscard]] std::string force_key(const LoadOrigin& o);
/// The load as a student reads it: "a strand of string s at pA", "the weight of A", "the force
/// on A", "the force of the sliding contact at P", else "the force of the " and the sentence.
[[nodiscard]] std::string force_phrase(const LoadOrigin& o);
/// Its couple as a student reads it: "the couple on A" (rule couple), else "the couple of the "
/// and the sentence.
[[nodiscard]] std::string couple_phrase(const LoadOrigin& o);
/// A term that comes from no load ("A after", "the length of string s") as a student reads it.
[[nodiscard]] std::string generic_phrase(const std::string& sentence);

}  // namespace tackle
