#pragma once
// What a study reports in summary.json: a Value, a tree of numbers, texts, lists and records (members in
// the order they were added), written the way a study thinks of its results,
//   ctx.summary["reproduced"]["sv_order"] = fit.order;
//   ctx.summary["h"] = {{"min", 0.01}, {"max", 0.1}};
// and read back with at(), number() and text(). It is one small class compiled once (runner/results.cpp);
// a study includes no JSON library, and only the runner turns the tree into summary.json
// (runner/results_json.hpp). Integers stay integers and reals reals, as JSON writes them ("3" and "3.0").
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace geomint {

class Value {
 public:
  enum class Kind : unsigned char { null, boolean, integer, unsigned_integer, real, text, list, record };
  struct Field;  // {key, value}: a record's member, for Value{{"min", a}, {"max", b}}

  Value() = default;  // null
  // (copied, moved and destroyed in results.cpp: compiled once, not in every file that writes a summary)
  Value(const Value&);
  Value(Value&&) noexcept;
  Value& operator=(const Value&);
  Value& operator=(Value&&) noexcept;
  ~Value();
  Value(std::nullptr_t) {}
  Value(bool b) : kind_(Kind::boolean), i_(b) {}
  Value(int v) : Value(static_cast<long long>(v)) {}
  Value(long v) : Value(static_cast<long long>(v)) {}
  Value(long long v) : kind_(Kind::integer), i_(v) {}
  Value(unsigned v) : Value(static_cast<unsigned long long>(v)) {}
  Value(unsigned long v) : Value(static_cast<unsigned long long>(v)) {}
  Value(unsigned long long v) : kind_(Kind::unsigned_integer), u_(v) {}
  Value(double v) : kind_(Kind::real), d_(v) {}
  Value(const char* s);  // (the texts too in results.cpp)
  Value(std::string s);
  Value(std::string_view s);
  Value(const std::optional<double>& v);        // the number, or null where there is none
  Value(const std::vector<double>& v);          // a list of numbers
  Value(const std::vector<std::string>& v);     // a list of texts
  Value(const std::vector<Value>& v);           // a list
  Value(std::initializer_list<Field> fields);  // a record
  static Value list() { return Value(Kind::list); }      // an empty list
  static Value record() { return Value(Kind::record); }  // an empty record

  Kind kind() const { return kind_; }
  bool is_null() const { return kind_ == Kind::null; }
  bool is_number() const { return kind_ == Kind::integer || kind_ == Kind::unsigned_integer || kind_ == Kind::real; }
  bool is_text() const { return kind_ == Kind::text; }
  bool is_list() const { return kind_ == Kind::list; }
  bool is_record() const { return kind_ == Kind::record; }

  // A record's member `key`, added (null) if absent; a null value becomes an empty record first.
  Value& operator[](std::string_view key);
  // The member `key` (std::out_of_range naming it if absent), or nullptr; whether there is one.
  const Value& at(std::string_view key) const;
  const Value* find(std::string_view key) const;
  bool contains(std::string_view key) const { return find(key) != nullptr; }
  const std::vector<std::string>& keys() const { return keys_; }  // a record's, in order

  // A list's element i (std::out_of_range if i >= size()), or a record's i-th member.
  const Value& at(std::size_t i) const;
  Value& at(std::size_t i);
  void push_back(Value v);    // appends to a list; a null value becomes an empty list first
  std::size_t size() const;   // elements of a list, members of a record; 0 for anything else

  // The content (std::logic_error naming the kind if it is another): number() of any number.
  double number() const;
  std::int64_t integer() const;
  bool boolean() const;
  const std::string& text() const;

  bool operator==(const Value& other) const;

 private:
  explicit Value(Kind k) : kind_(k) {}
  Kind kind_ = Kind::null;
  std::int64_t i_ = 0;   // boolean, integer
  std::uint64_t u_ = 0;  // unsigned_integer
  double d_ = 0;         // real
  std::string s_;        // text
  std::vector<std::string> keys_;  // record: the members' keys, in order
  std::vector<Value> items_;       // list: the elements; record: the members' values
};

struct Value::Field {
  std::string_view key;  // (copied by the record: a temporary key lives as long as the braces)
  Value value;
};

// Sets summary[section][k] = v for every member k of the record `values` (other studies may have filled
// part of the section already; an empty `values` adds nothing, not even the section).
void merge(Value& summary, const char* section, const Value& values);

// The kind in words ("a number", "a record", ...), for messages.
std::string_view kind_name(Value::Kind k);

}  // namespace geomint
