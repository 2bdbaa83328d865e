// Helpers for tests of bad scenarios: parse, catch the ScenarioError, check its one-line message.
#pragma once

#include "tumble/scenario/scenario.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace tumble::scenario::test_support {

/// The error parseScenario throws for `text` (as "scene.toml"), or none.
inline std::optional<ScenarioError> parseError(std::string_view text,
                                               std::span<const std::string> overrides = {})
{
    try {
        (void)parseScenario(text, "scene.toml", overrides);
    } catch (const ScenarioError& error) {
        return error;
    }
    return std::nullopt;
}

/// Passes when parsing `text` fails with a message that starts with `prefix` ("FILE:LINE: KEY: ")
/// and contains `fragment`.
inline ::testing::AssertionResult failsWith(std::string_view text, std::string_view prefix,
                                            std::string_view fragment,
                                            std::span<const std::string> overrides = {})
{
    const std::optional<ScenarioError> error = parseError(text, overrides);
    if (!error) {
        return ::testing::AssertionFailure() << "parsed without a ScenarioError";
    }
    const std::string message = error->what();
    if (!message.starts_with(prefix) || message.find(fragment) == std::string::npos) {
        return ::testing::AssertionFailure()
               << "message \"" << message << "\" does not start with \"" << prefix
               << "\" and contain \"" << fragment << "\"";
    }
    if (message.find('\n') != std::string::npos) {
        return ::testing::AssertionFailure() << "message is not one line: \"" << message << "\"";
    }
    return ::testing::AssertionSuccess() << message;
}

} // namespace tumble::scenario::test_support
