// A bump allocator for AST nodes: trivially destructible objects, freed all at once.
#pragma once

#include <cstddef>
#include <cstring>
#include <memory>
#include <new>
#include <span>
#include <string_view>
#include <type_traits>
#include <vector>

namespace crt::lang {

class Arena {
public:
    Arena() = default;
    Arena(const Arena&) = delete;
    Arena& operator=(const Arena&) = delete;

    void* allocate(size_t size, size_t align) {
        size_t offset = (used_ + align - 1) & ~(align - 1);
        if (chunks_.empty() || offset + size > capacity_) {
            capacity_ = std::max(kChunkSize, size + align);
            chunks_.push_back(std::unique_ptr<std::byte[]>(new std::byte[capacity_])); // not zeroed
            offset = 0;
            used_ = 0;
        }
        used_ = offset + size;
        bytes_ += size;
        return chunks_.back().get() + offset;
    }

    template <typename T, typename... Args> T* make(Args&&... args) {
        static_assert(std::is_trivially_destructible_v<T>, "arena objects are never destroyed");
        return new (allocate(sizeof(T), alignof(T))) T{std::forward<Args>(args)...};
    }

    /// Copies `items` into the arena.
    template <typename T> std::span<T> copy(const std::vector<T>& items) {
        static_assert(std::is_trivially_copyable_v<T>);
        if (items.empty()) return {};
        T* data = static_cast<T*>(allocate(sizeof(T) * items.size(), alignof(T)));
        std::memcpy(static_cast<void*>(data), items.data(), sizeof(T) * items.size());
        return {data, items.size()};
    }

    std::string_view copy(std::string_view text) {
        if (text.empty()) return {};
        char* data = static_cast<char*>(allocate(text.size(), 1));
        std::memcpy(data, text.data(), text.size());
        return {data, text.size()};
    }

    size_t bytesAllocated() const { return bytes_; }

private:
    static constexpr size_t kChunkSize = 64 * 1024;
    std::vector<std::unique_ptr<std::byte[]>> chunks_;
    size_t capacity_ = 0;
    size_t used_ = 0;
    size_t bytes_ = 0;
};

} // namespace crt::lang
