// A reference to a callable, cheap to pass and owning nothing (as C++26's std::function_ref).
#pragma once

namespace crt::tracer {

template <typename Signature> class FunctionRef;

/// Refers to a callable R(Args...) that outlives it; made implicitly from the callable, so a
/// lambda can be passed where one is taken. Unlike a template parameter it is one type
/// whatever it refers to, so a function taking it is compiled once.
template <typename R, typename... Args> class FunctionRef<R(Args...)> {
  public:
    template <typename F>
    FunctionRef(F& f) // NOLINT: made implicitly from the callable it refers to
        : context_(&f), call_([](void* c, Args... args) -> R { return (*static_cast<F*>(c))(args...); }) {}
    R operator()(Args... args) const { return call_(context_, args...); }

  private:
    void* context_;
    R (*call_)(void*, Args...);
};

} // namespace crt::tracer
