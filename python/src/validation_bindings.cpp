// The engine of tumble.validate: the validation suite's cases (tumble/validation) run without the
// GIL, one row per checked quantity.
#include "bindings.hpp"
#include "long_call.hpp"

#include "tumble/validation/validation.hpp"

#include <pybind11/stl.h>

#include <string>
#include <tuple>
#include <vector>

namespace tumble::python {
namespace {

/// case, section, quantity, dt, exact, value, error, tolerance, passed, unit, expected order.
using Row = std::tuple<std::string, std::string, std::string, double, double, double, double,
                       double, bool, std::string, int>;

py::list validationRows(const std::vector<double>& steps, const py::object& progress)
{
    const std::vector<validation::Case> cases = validation::cases();
    const auto runs = static_cast<std::int64_t>(cases.size() * steps.size());
    LongCall call(progress, runs, "runs");
    std::vector<Row> rows;
    std::int64_t done = 0;
    {
        const py::gil_scoped_release release;
        for (const double dt : steps) {
            for (const validation::Case& c : cases) {
                if (call.poll(done)) {
                    break;
                }
                for (const validation::Quantity& q : c.run(dt)) {
                    rows.emplace_back(c.name, c.section, q.name, dt, q.exact, q.value, q.error(),
                                      q.tolerance, q.passes(), q.unit, c.expectedOrder);
                }
                ++done;
            }
        }
    }
    py::list result = py::cast(rows);
    call.finish(done, result);
    return result;
}

} // namespace

void bindValidation(py::module_& module)
{
    module.def("_validation_rows", &validationRows, py::arg("steps"), py::arg("progress"),
               "The validation table as tuples; see tumble.validate.");
}

} // namespace tumble::python
