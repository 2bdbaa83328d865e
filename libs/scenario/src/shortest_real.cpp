#include "shortest_real.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace tumble::scenario::detail {
namespace {

/// The significant digits of the shortest round-trip form and the decimal exponent of the first.
struct Digits {
    std::string digits;
    int exponent = 0;
};

Digits shortestDigits(double value)
{
    // %.*e gives the correctly rounded digits; the first precision that reads back is the shortest
    char buffer[64];
    for (int precision = 0; precision < 17; ++precision) {
        std::snprintf(buffer, sizeof buffer, "%.*e", precision, value);
        if (std::strtod(buffer, nullptr) == value) {
            break;
        }
    }
    const std::string text = buffer;
    const std::size_t e = text.find('e');
    Digits result;
    for (std::size_t i = 0; i < e; ++i) {
        if (text[i] >= '0' && text[i] <= '9') {
            result.digits += text[i];
        }
    }
    result.exponent = std::atoi(text.c_str() + e + 1);
    return result;
}

/// `magnitude` is the value the digits round-trip to.
std::string fixedForm(const Digits& d, double magnitude)
{
    const int count = static_cast<int>(d.digits.size());
    // strings are appended, not chained with operator+ (GCC 12 warns falsely, -Wrestrict)
    if (d.exponent < 0) {
        std::string text = "0.";
        text.append(static_cast<std::size_t>(-d.exponent - 1), '0');
        text += d.digits;
        return text;
    }
    if (d.exponent + 1 >= count) {
        // a whole number is written with its exact digits (as long as the padded form), as
        // libstdc++'s and MSVC's to_chars do: 3890112603894059008, not ...059000
        char exact[400];
        std::snprintf(exact, sizeof exact, "%.0f", magnitude);
        return exact;
    }
    const auto point = static_cast<std::size_t>(d.exponent + 1);
    std::string text = d.digits.substr(0, point);
    text += '.';
    text += d.digits.substr(point);
    return text;
}

std::string scientificForm(const Digits& d)
{
    std::string text = d.digits.substr(0, 1);
    if (d.digits.size() > 1) {
        text += '.';
        text += d.digits.substr(1);
    }
    char exponent[16];
    std::snprintf(exponent, sizeof exponent, "e%c%02d", d.exponent < 0 ? '-' : '+',
                  d.exponent < 0 ? -d.exponent : d.exponent);
    text += exponent;
    return text;
}

} // namespace

std::string shortestReal(double value)
{
    if (value == 0.0) {
        return std::signbit(value) ? "-0" : "0";
    }
    const double magnitude = std::fabs(value);
    const Digits digits = shortestDigits(magnitude);
    const std::string fixed = fixedForm(digits, magnitude);
    const std::string scientific = scientificForm(digits);
    // fixed wins a tie, as in to_chars
    std::string text = value < 0.0 ? "-" : "";
    text += scientific.size() < fixed.size() ? scientific : fixed;
    return text;
}

} // namespace tumble::scenario::detail
