#pragma once
// A registered method by name, bound to a system at compile time (with_method, with_kernel): the dispatch over
// registered_methods (methods.hpp), which instantiates every method that can step the system, the odeint ones
// included (reference/odeint_steppers.hpp: Boost.Odeint). The library compiles it once per system
// (methods/by_name_impl.hpp, the generated on_<system>.cpp); a study calls MethodsOn (by_name.hpp) instead.
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "geomint/methods/methods.hpp"
#include "geomint/reference/odeint_steppers.hpp"

namespace geomint {

namespace detail {
struct BindMethod {
  template <class M, class Sys>
  static auto bind(const Sys& sys) { return M::bind(sys); }
};
struct BindKernel {
  template <class M, class Sys>
  static auto bind(const Sys& sys) {
    if constexpr (requires { M::bind_kernel(sys); }) return M::bind_kernel(sys);
    else return M::bind(sys);
  }
};

template <class Binder, class Sys, class F, class M>
struct BoundResult {
  using type = std::invoke_result_t<F&, decltype(Binder::template bind<M>(std::declval<const Sys&>()))>;
};
// What f returns for the first method of the list that binds to Sys (void if none does).
template <class Binder, class Sys, class F, class... Ms>
struct DispatchResult {
  using type = void;
};
template <class Binder, class Sys, class F, class M, class... Ms>
struct DispatchResult<Binder, Sys, F, M, Ms...> {
  using type = typename std::conditional_t<Binds<M, Sys>, BoundResult<Binder, Sys, F, M>,
                                           DispatchResult<Binder, Sys, F, Ms...>>::type;
};

template <class R, class Binder, class Sys, class F, class M, class... Ms>
R dispatch(std::string_view name, const Sys& sys, F& f) {
  if (name == M::info.name || name == M::info.label) {
    if constexpr (Binds<M, Sys>) {
      return f(Binder::template bind<M>(sys));
    } else {
      throw std::invalid_argument("method " + std::string(M::info.name) + " cannot step this system (it steps: " +
                                  std::string(M::info.applies_to) + ")");
    }
  }
  if constexpr (sizeof...(Ms) > 0) {
    return dispatch<R, Binder, Sys, F, Ms...>(name, sys, f);
  } else {
    method_info(name);  // throws, naming the valid names
    throw std::logic_error("registered_methods and method_registry() disagree");
  }
}

template <class Binder, class Sys, class F, class... Ms>
decltype(auto) with(MethodList<Ms...>, std::string_view name, const Sys& sys, F& f) {
  using R = typename DispatchResult<Binder, Sys, F, Ms...>::type;
  return dispatch<R, Binder, Sys, F, Ms...>(name, sys, f);
}

}  // namespace detail

// f(method bound to sys); throws std::invalid_argument if the name is unknown or the method cannot step Sys.
template <class Sys, class F>
decltype(auto) with_method(std::string_view name_or_label, const Sys& sys, F&& f) {
  return detail::with<detail::BindMethod>(registered_methods{}, name_or_label, sys, f);
}

// The same with the kernel of a processed method, with trivial processors (the method itself otherwise).
template <class Sys, class F>
decltype(auto) with_kernel(std::string_view name_or_label, const Sys& sys, F&& f) {
  return detail::with<detail::BindKernel>(registered_methods{}, name_or_label, sys, f);
}

}  // namespace geomint
