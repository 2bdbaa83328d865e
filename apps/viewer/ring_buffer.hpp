// RingBuffer: a fixed-capacity buffer that keeps the newest values, for the live plots and the
// log panel.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace tumble::viewer {

/// Keeps the last `capacity` values pushed; index 0 is the oldest kept.
template <typename T>
class RingBuffer {
public:
    explicit RingBuffer(std::size_t capacity) : m_storage(capacity > 0 ? capacity : 1) {}

    void push(T value)
    {
        m_storage[(m_start + m_size) % m_storage.size()] = std::move(value);
        if (m_size < m_storage.size()) {
            ++m_size;
        } else {
            m_start = (m_start + 1) % m_storage.size();
        }
    }

    void clear()
    {
        m_start = 0;
        m_size = 0;
    }

    [[nodiscard]] std::size_t size() const { return m_size; }
    [[nodiscard]] std::size_t capacity() const { return m_storage.size(); }
    [[nodiscard]] bool empty() const { return m_size == 0; }
    /// The i-th oldest value kept (0 <= i < size()).
    [[nodiscard]] const T& operator[](std::size_t i) const
    {
        return m_storage[(m_start + i) % m_storage.size()];
    }
    [[nodiscard]] const T& front() const { return (*this)[0]; }
    [[nodiscard]] const T& back() const { return (*this)[m_size - 1]; }

    /// Drops the oldest values while `predicate(oldest)` holds.
    template <typename Predicate>
    void dropWhile(Predicate predicate)
    {
        while (m_size > 0 && predicate(front())) {
            m_start = (m_start + 1) % m_storage.size();
            --m_size;
        }
    }

private:
    std::vector<T> m_storage;
    std::size_t m_start = 0;
    std::size_t m_size = 0;
};

} // namespace tumble::viewer
