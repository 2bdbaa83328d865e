// Text for scenario error messages: numbers and vectors, node descriptions, unknown-key hints.
#include "messages.hpp"

#include "shortest_real.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <vector>

namespace tumble::scenario::detail {

std::string formatReal(Real value)
{
    if (std::isnan(value)) {
        return "nan";
    }
    if (std::isinf(value)) {
        return value > 0 ? "inf" : "-inf";
    }
#if defined(__cpp_lib_to_chars)
    std::array<char, 64> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return std::string(buffer.data(), result.ptr);
#else
    return shortestReal(value);
#endif
}

std::string formatVec3(const Vec3& value)
{
    // Appended piece by piece: GCC 12 at -O3 warns (-Wrestrict, a false positive) on a chain of
    // operator+ that starts from a literal.
    std::string text = "[";
    text += formatReal(value.x);
    text += ", ";
    text += formatReal(value.y);
    text += ", ";
    text += formatReal(value.z);
    text += "]";
    return text;
}

int editDistance(std::string_view a, std::string_view b)
{
    std::vector<int> previous(b.size() + 1);
    std::vector<int> current(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) {
        previous[j] = static_cast<int>(j);
    }
    for (std::size_t i = 1; i <= a.size(); ++i) {
        current[0] = static_cast<int>(i);
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const int substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
        }
        std::swap(previous, current);
    }
    return previous[b.size()];
}

std::string unknownKeyProblem(std::string_view key, std::span<const std::string_view> known)
{
    std::string problem = "unknown key '" + std::string(key) + "'";
    std::string_view best;
    int bestDistance = 3;
    for (const std::string_view candidate : known) {
        const int distance = editDistance(key, candidate);
        if (distance < bestDistance) {
            bestDistance = distance;
            best = candidate;
        }
    }
    if (!best.empty()) {
        return problem + " (did you mean '" + std::string(best) + "'?)";
    }
    problem += " (known keys:";
    for (const std::string_view candidate : known) {
        problem += ' ';
        problem += candidate;
    }
    return problem + ")";
}

std::string describeNode(const toml::node& node)
{
    switch (node.type()) {
    case toml::node_type::string:
        return "a string (\"" + std::string(*node.as_string()) + "\")";
    case toml::node_type::integer:
        return "an integer";
    case toml::node_type::floating_point:
        return "a number";
    case toml::node_type::boolean:
        return "a boolean";
    case toml::node_type::array: {
        const std::size_t count = node.as_array()->size();
        return "an array of " + std::to_string(count) + (count == 1 ? " value" : " values");
    }
    case toml::node_type::table:
        return "a table";
    case toml::node_type::date:
        return "a date";
    case toml::node_type::time:
        return "a time";
    case toml::node_type::date_time:
        return "a date-time";
    case toml::node_type::none:
        break;
    }
    return "nothing";
}

} // namespace tumble::scenario::detail
