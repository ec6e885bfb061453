#pragma once
// How a C++ field type is stored as a parameter value, and read back. One specialisation per
// family of types, so that a config struct can bind its fields by type alone:
//   bool -> bool; integers -> int; floating types -> float; std::string -> string;
//   std::vector<double> -> float list; fixed-size vectors (std::array<double, N>, or any type with
//   a compile-time size such as Eigen::Vector3d) -> float list of exactly N; ComponentConfig ->
//   component. The runtime itself knows no vector library: fixed-size vectors are recognised by
//   their shape.
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "kestrel/error.hpp"
#include "kestrel/param_value.hpp"

namespace kestrel {

namespace detail {
/// A column vector whose length is known at compile time (Eigen::Matrix<double, N, 1>).
template <class T>
concept FixedColumnVector = requires(T v) {
  { T::RowsAtCompileTime } -> std::convertible_to<int>;
  { T::ColsAtCompileTime } -> std::convertible_to<int>;
  requires T::ColsAtCompileTime == 1 && T::RowsAtCompileTime > 0;
  { v[0] } -> std::convertible_to<double>;
};

template <class T>
struct is_std_array : std::false_type {};
template <std::size_t N>
struct is_std_array<std::array<double, N>> : std::true_type {};

[[noreturn]] void throw_wrong_type(const std::string& name, const ParamValue& value, const char* wanted);
}  // namespace detail

template <class T, class Enable = void>
struct ParamCodec {
  static_assert(sizeof(T) == 0,
                "unsupported parameter type: use bool, an integer, a floating type, std::string, "
                "std::vector<double>, a fixed-size vector of doubles, ComponentConfig or an enum with choice()");
};

template <>
struct ParamCodec<bool> {
  static constexpr ParamType type = ParamType::boolean;
  static constexpr std::size_t length = 0;
  static ParamValue encode(bool v) { return v; }
  static bool decode(const ParamValue& v, const std::string& name) {
    if (auto* b = std::get_if<bool>(&v)) return *b;
    detail::throw_wrong_type(name, v, "bool");
  }
};

template <class T>
struct ParamCodec<T, std::enable_if_t<std::is_integral_v<T> && !std::is_same_v<T, bool>>> {
  static constexpr ParamType type = ParamType::integer;
  static constexpr std::size_t length = 0;
  static ParamValue encode(T v) { return static_cast<std::int64_t>(v); }
  static T decode(const ParamValue& v, const std::string& name) {
    auto* i = std::get_if<std::int64_t>(&v);
    if (!i) detail::throw_wrong_type(name, v, "int");
    if (*i < static_cast<std::int64_t>(std::numeric_limits<T>::min()) ||
        (*i > 0 && static_cast<std::uint64_t>(*i) > static_cast<std::uint64_t>(std::numeric_limits<T>::max())))
      throw Error("parameter '" + name + "' = " + std::to_string(*i) + " does not fit the node's integer type");
    return static_cast<T>(*i);
  }
};

template <class T>
struct ParamCodec<T, std::enable_if_t<std::is_floating_point_v<T>>> {
  static constexpr ParamType type = ParamType::number;
  static constexpr std::size_t length = 0;
  static ParamValue encode(T v) { return static_cast<double>(v); }
  static T decode(const ParamValue& v, const std::string& name) {
    if (auto* d = std::get_if<double>(&v)) return static_cast<T>(*d);
    if (auto* i = std::get_if<std::int64_t>(&v)) return static_cast<T>(*i);  // integers widen on request
    detail::throw_wrong_type(name, v, "float");
  }
};

template <>
struct ParamCodec<std::string> {
  static constexpr ParamType type = ParamType::string;
  static constexpr std::size_t length = 0;
  static ParamValue encode(const std::string& v) { return v; }
  static std::string decode(const ParamValue& v, const std::string& name) {
    if (auto* s = std::get_if<std::string>(&v)) return *s;
    detail::throw_wrong_type(name, v, "string");
  }
};

template <>
struct ParamCodec<std::vector<double>> {
  static constexpr ParamType type = ParamType::number_list;
  static constexpr std::size_t length = 0;  // any length
  static ParamValue encode(const std::vector<double>& v) { return v; }
  static std::vector<double> decode(const ParamValue& v, const std::string& name) {
    if (auto* l = std::get_if<std::vector<double>>(&v)) return *l;
    detail::throw_wrong_type(name, v, "float list");
  }
};

/// std::array<double, N> and fixed-size column vectors: a list of exactly N numbers.
template <class T>
struct ParamCodec<T, std::enable_if_t<detail::FixedColumnVector<T> || detail::is_std_array<T>::value>> {
  static constexpr ParamType type = ParamType::number_list;
  static constexpr std::size_t length = [] {
    if constexpr (detail::is_std_array<T>::value)
      return std::tuple_size<T>::value;
    else
      return static_cast<std::size_t>(T::RowsAtCompileTime);
  }();
  static ParamValue encode(const T& v) {
    std::vector<double> list(length);
    for (std::size_t i = 0; i < length; ++i) list[i] = static_cast<double>(v[static_cast<int>(i)]);
    return list;
  }
  static T decode(const ParamValue& v, const std::string& name) {
    auto* l = std::get_if<std::vector<double>>(&v);
    if (!l || l->size() != length) detail::throw_wrong_type(name, v, "float list of fixed length");
    T out{};
    for (std::size_t i = 0; i < length; ++i) out[static_cast<int>(i)] = (*l)[i];
    return out;
  }
};

template <>
struct ParamCodec<ComponentConfig> {
  static constexpr ParamType type = ParamType::component;
  static constexpr std::size_t length = 0;
  static ParamValue encode(const ComponentConfig& v) { return v; }
  static ComponentConfig decode(const ParamValue& v, const std::string& name) {
    if (auto* c = std::get_if<ComponentConfig>(&v)) return *c;
    detail::throw_wrong_type(name, v, "component");
  }
};

}  // namespace kestrel
