// Every kind of bad input the robustness tests feed the scenario loader, with a piece of the
// message tumble must answer with. bad_input_test.cpp checks each row; robustness_doc.cpp writes
// the table (with tumble's actual messages) into docs/robustness.md.
#pragma once

#include <string_view>
#include <vector>

namespace tumble::robustness {

struct BadInput {
    /// What is wrong, for the document.
    std::string_view kind;
    /// The scenario text.
    std::string_view text;
    /// A --set override applied to it (empty for none).
    std::string_view override;
    /// Part of the expected one-line message.
    std::string_view expected;
};

inline const std::vector<BadInput>& badInputs()
{
    static const std::vector<BadInput> inputs{
        {"empty file", "", "", "a scenario needs at least one [[body]]"},
        {"binary garbage", "\x01\x02\xff\xfe\x00\x7f", "", "TOML syntax error"},
        {"TOML syntax error", "[[body]]\nmass = \n", "", "TOML syntax error"},
        {"unterminated string", "[[body]]\nname = \"rb\n", "", "TOML syntax error"},
        {"deeply nested arrays", "[[body]]\nsize = [[[[[[[[[[[[[[[[[[[[1]]]]]]]]]]]]]]]]]]]]\n", "",
         "body[0].size"},
        {"integer beyond 64 bits", "[[body]]\nmass = 99999999999999999999\n", "",
         "TOML syntax error"},
        {"unknown top-level table", "[wrld]\n[[body]]\n", "", "unknown key 'wrld'"},
        {"misspelt key", "[[body]]\nelasticty = 0.5\n", "", "did you mean 'elasticity'?"},
        {"[[body]] missing", "[world]\ndt = 0.01\n", "", "a scenario needs at least one [[body]]"},
        {"body not an array of tables", "body = 3\n", "", "expected an array of tables"},
        {"string for a number", "[[body]]\nmass = \"heavy\"\n", "", "expected a number"},
        {"float for an integer", "[world]\nsolver_iterations = 8.0\n[[body]]\n", "",
         "expected an integer"},
        {"vector of 2 numbers", "[[body]]\nvelocity = [1, 2]\n", "",
         "expected an array of 3 numbers"},
        {"nan", "[[body]]\nmass = nan\n", "", "must be finite"},
        {"infinity", "[[body]]\nposition = [0, inf, 0]\n", "", "must be finite"},
        {"negative mass", "[[body]]\nmass = -2\n", "", "must be > 0, got -2"},
        {"zero mass", "[[body]]\nmass = 0\n", "", "must be > 0, got 0"},
        {"mass above the valid range", "[[body]]\nmass = 1e7\n", "",
         "must be between 1e-06 and 1e+06 kg, got 1e+07"},
        {"mass below the valid range", "[[body]]\nmass = 1e-9\n", "",
         "must be between 1e-06 and 1e+06 kg"},
        {"zero size", "[[body]]\nsize = [1, 0, 1]\n", "", "every component must be > 0"},
        {"edge below the valid range", "[[body]]\nsize = [1, 1e-4, 1]\n", "",
         "every edge must be between 0.001 and 1000 m"},
        {"edge above the valid range", "[[body]]\nscale = [1, 1, 1e4]\n", "",
         "every edge must be between 0.001 and 1000 m"},
        {"aspect ratio above 1:1000", "[[body]]\nsize = [0.01, 20, 1]\n", "",
         "the longest edge over the shortest must be between 1 and 1000"},
        {"size and scale together", "[[body]]\nsize = [1, 1, 1]\nscale = [1, 1, 1]\n", "",
         "give size or scale, not both"},
        {"position far from the origin", "[[body]]\nposition = [0, 2e6, 0]\n", "",
         "the distance from the origin must be at most 1e+06 m"},
        {"speed above the valid range", "[[body]]\nvelocity = [0, -2000, 0]\n", "",
         "the speed must be at most 1000 m/s"},
        {"angular speed above the valid range", "[[body]]\nangular_velocity = [0, 2000, 0]\n",
         "", "the angular speed must be at most 1000 rad/s"},
        {"too fast a spin for the step",
         "[world]\ndt = 0.01\n[[body]]\nangular_velocity = [0, 100, 0]\n", "",
         "the angle turned in one step"},
        {"elasticity above 1", "[[body]]\nelasticity = 1.5\n", "", "must be in [0, 1]"},
        {"negative friction", "[[body]]\nfriction = -0.1\n", "", "must be >= 0"},
        {"friction above the valid range", "[[body]]\nfriction = 20\n", "",
         "must be at most 10, got 20"},
        {"static friction below kinetic", "[[body]]\nfriction = 0.5\nstatic_friction = 0.2\n", "",
         "must be >= friction"},
        {"quaternion not of unit length", "[[body]]\norientation = [1, 0.1, 0, 0]\n", "",
         "not a unit quaternion"},
        {"zero rotation axis", "[[body]]\norientation = { axis = [0, 0, 0], degrees = 30 }\n", "",
         "must be a nonzero vector"},
        {"duplicate body names", "[[body]]\nname = \"a\"\n[[body]]\nname = \"a\"\n", "",
         "duplicate body name"},
        {"empty body name", "[[body]]\nname = \"\"\n", "", "must not be empty"},
        {"zero dt", "[world]\ndt = 0\n[[body]]\n", "", "must be > 0, got 0"},
        {"dt above the valid range", "[world]\ndt = 0.5\n[[body]]\n", "",
         "must be between 1e-06 and 0.1 s"},
        {"dt below the valid range", "[world]\ndt = 1e-9\n[[body]]\n", "",
         "must be between 1e-06 and 0.1 s"},
        {"more than 10^9 steps", "[world]\ndt = 1e-6\nduration = 1e4\n[[body]]\n", "",
         "the number of steps duration / dt must be at most 1e+09 steps"},
        {"gravity above the valid range", "[world]\ngravity = [0, -1e4, 0]\n[[body]]\n", "",
         "the length must be at most 1000 m/s^2"},
        {"contact tolerance above the valid range",
         "[world]\ncontact_tolerance = 1\n[[body]]\n", "", "must be between 1e-09 and 0.01 m"},
        {"ground far away", "[ground]\nheight = -1e7\n[[body]]\n", "",
         "must be between -1e+06 and 1e+06 m"},
        {"solver iterations below 1", "[world]\nsolver_iterations = 0\n[[body]]\n", "",
         "must be between 1 and 1000000"},
        {"unknown integrator", "[world]\nintegrator = \"euler\"\n[[body]]\n", "",
         "must be one of \"exact\", \"handout\""},
        {"impulse on an unknown body", "[[body]]\n[[impulse]]\nat = 1\nbody = \"box\"\nimpulse = [1, 0, 0]\n",
         "", "no body named \"box\""},
        {"impulse without at", "[[body]]\n[[impulse]]\nbody = \"body1\"\nimpulse = [1, 0, 0]\n", "",
         "missing: the time"},
        {"impulse at a negative time",
         "[[body]]\n[[impulse]]\nat = -1\nbody = \"body1\"\nimpulse = [1, 0, 0]\n", "",
         "must be >= 0"},
        {"impulse and target together",
         "[[body]]\n[[impulse]]\nat = 1\nbody = \"body1\"\nimpulse = [1, 0, 0]\nvelocity = [0, 0, 0]\n",
         "", "not both"},
        {"half a target",
         "[[body]]\n[[impulse]]\nat = 1\nbody = \"body1\"\nvelocity = [0, 0, 0]\n", "",
         "a target needs both velocity and angular_velocity"},
        {"impulse above the valid range",
         "[[body]]\n[[impulse]]\nat = 1\nbody = \"body1\"\nimpulse = [1e10, 0, 0]\n", "",
         "the length must be at most 1e+09 N s"},
        {"offset far outside any body",
         "[[body]]\n[[impulse]]\nat = 1\nbody = \"body1\"\nimpulse = [1, 0, 0]\noffset = [0, 1e4, 0]\n",
         "", "the length must be at most 1000 m"},
        {"override of an unknown body", "[[body]]\nname = \"rb\"\n", "box.mass=1",
         "no body named 'box'"},
        {"override with an unknown key", "[[body]]\nname = \"rb\"\n", "rb.mas=1",
         "did you mean 'mass'?"},
        {"override outside the valid range", "[[body]]\nname = \"rb\"\n", "world.dt=1",
         "must be between 1e-06 and 0.1 s"},
        {"override that is not TOML", "[[body]]\nname = \"rb\"\n", "world.dt=[1,", ""},
    };
    return inputs;
}

} // namespace tumble::robustness
