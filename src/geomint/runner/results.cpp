#include "geomint/runner/results.hpp"

#include <stdexcept>
#include <utility>

#include "geomint/runner/results_json.hpp"

namespace geomint {

Value::Value(const Value&) = default;
Value::Value(Value&&) noexcept = default;
Value& Value::operator=(const Value&) = default;
Value& Value::operator=(Value&&) noexcept = default;
Value::~Value() = default;

Value::Value(const std::optional<double>& v) {
  if (v) kind_ = Kind::real, d_ = *v;
}

Value::Value(const std::vector<double>& v) : kind_(Kind::list) {
  items_.assign(v.begin(), v.end());
}

Value::Value(const std::vector<std::string>& v) : kind_(Kind::list) {
  items_.assign(v.begin(), v.end());
}

Value::Value(const std::vector<Value>& v) : kind_(Kind::list), items_(v) {}

Value::Value(const char* s) : kind_(Kind::text), s_(s) {}
Value::Value(std::string s) : kind_(Kind::text), s_(std::move(s)) {}
Value::Value(std::string_view s) : kind_(Kind::text), s_(s) {}

Value::Value(std::initializer_list<Field> fields) : kind_(Kind::record) {
  for (const Field& f : fields) (*this)[f.key] = f.value;
}

std::string_view kind_name(Value::Kind k) {
  switch (k) {
    case Value::Kind::null: return "null";
    case Value::Kind::boolean: return "a boolean";
    case Value::Kind::integer:
    case Value::Kind::unsigned_integer:
    case Value::Kind::real: return "a number";
    case Value::Kind::text: return "a text";
    case Value::Kind::list: return "a list";
    case Value::Kind::record: return "a record";
  }
  return "?";
}

namespace {
[[noreturn]] void wrong_kind(Value::Kind is, std::string_view wanted) {
  throw std::logic_error("summary value: " + std::string(kind_name(is)) + " where " + std::string(wanted) +
                         " was expected");
}
}  // namespace

Value& Value::operator[](std::string_view key) {
  if (kind_ == Kind::null) kind_ = Kind::record;
  if (kind_ != Kind::record) wrong_kind(kind_, "a record");
  for (std::size_t i = 0; i < keys_.size(); ++i)
    if (keys_[i] == key) return items_[i];
  keys_.emplace_back(key);
  items_.emplace_back();
  return items_.back();
}

const Value* Value::find(std::string_view key) const {
  if (kind_ != Kind::record) return nullptr;
  for (std::size_t i = 0; i < keys_.size(); ++i)
    if (keys_[i] == key) return &items_[i];
  return nullptr;
}

const Value& Value::at(std::string_view key) const {
  const Value* v = find(key);
  if (!v) throw std::out_of_range("summary value: no member \"" + std::string(key) + "\"");
  return *v;
}

const Value& Value::at(std::size_t i) const {
  if ((kind_ != Kind::list && kind_ != Kind::record) || i >= items_.size())
    throw std::out_of_range("summary value: no element " + std::to_string(i));
  return items_[i];
}

Value& Value::at(std::size_t i) {
  return const_cast<Value&>(std::as_const(*this).at(i));
}

void Value::push_back(Value v) {
  if (kind_ == Kind::null) kind_ = Kind::list;
  if (kind_ != Kind::list) wrong_kind(kind_, "a list");
  items_.push_back(std::move(v));
}

std::size_t Value::size() const {
  return kind_ == Kind::list || kind_ == Kind::record ? items_.size() : 0;
}

double Value::number() const {
  switch (kind_) {
    case Kind::integer: return static_cast<double>(i_);
    case Kind::unsigned_integer: return static_cast<double>(u_);
    case Kind::real: return d_;
    default: wrong_kind(kind_, "a number");
  }
}

std::int64_t Value::integer() const {
  if (kind_ == Kind::integer) return i_;
  if (kind_ == Kind::unsigned_integer) return static_cast<std::int64_t>(u_);
  wrong_kind(kind_, "an integer");
}

bool Value::boolean() const {
  if (kind_ != Kind::boolean) wrong_kind(kind_, "a boolean");
  return i_ != 0;
}

const std::string& Value::text() const {
  if (kind_ != Kind::text) wrong_kind(kind_, "a text");
  return s_;
}

void merge(Value& summary, const char* section, const Value& values) {
  for (std::size_t i = 0; i < values.keys().size(); ++i) summary[section][values.keys()[i]] = values.at(i);
}

bool Value::operator==(const Value& o) const {
  if (is_number() && o.is_number()) return to_json(*this) == to_json(o);  // (JSON's rule across integer kinds)
  return kind_ == o.kind_ && i_ == o.i_ && u_ == o.u_ && s_ == o.s_ && keys_ == o.keys_ && items_ == o.items_ &&
         (kind_ != Kind::real || d_ == o.d_);
}

nlohmann::ordered_json to_json(const Value& v) {
  using J = nlohmann::ordered_json;
  switch (v.kind()) {
    case Value::Kind::null: return nullptr;
    case Value::Kind::boolean: return v.boolean();
    case Value::Kind::integer: return v.integer();
    case Value::Kind::unsigned_integer: return static_cast<std::uint64_t>(v.integer());
    case Value::Kind::real: return v.number();
    case Value::Kind::text: return v.text();
    case Value::Kind::list: {
      J out = J::array();
      for (std::size_t i = 0; i < v.size(); ++i) out.push_back(to_json(v.at(i)));
      return out;
    }
    case Value::Kind::record: {
      J out = J::object();
      for (std::size_t i = 0; i < v.size(); ++i) out[v.keys()[i]] = to_json(v.at(i));
      return out;
    }
  }
  return nullptr;
}

Value value_of(const nlohmann::ordered_json& j) {
  switch (j.type()) {
    case nlohmann::ordered_json::value_t::boolean: return j.get<bool>();
    case nlohmann::ordered_json::value_t::number_integer: return j.get<std::int64_t>();
    case nlohmann::ordered_json::value_t::number_unsigned: return j.get<std::uint64_t>();
    case nlohmann::ordered_json::value_t::number_float: return j.get<double>();
    case nlohmann::ordered_json::value_t::string: return j.get<std::string>();
    case nlohmann::ordered_json::value_t::array: {
      Value out = Value::list();
      for (const auto& e : j) out.push_back(value_of(e));
      return out;
    }
    case nlohmann::ordered_json::value_t::object: {
      Value out = Value::record();
      for (const auto& [k, e] : j.items()) out[k] = value_of(e);
      return out;
    }
    default: return nullptr;
  }
}

}  // namespace geomint
