// A shape held behind a pointer, so that a variant of shapes is as small as its small ones.
#pragma once

#include <memory>
#include <utility>

namespace crt::tracer {

/// An immutable T on the heap, shared by the copies (a shape does not change once made, so
/// the copies of a primitive that instancing and CSG make need not copy it).
template <typename T>
class OutOfLine {
public:
    OutOfLine(T value) : value_(std::make_shared<const T>(std::move(value))) {}

    const T& operator*() const { return *value_; }
    const T* operator->() const { return value_.get(); }

private:
    std::shared_ptr<const T> value_;
};

} // namespace crt::tracer
