// LongCall: polling Python's signal handlers and the progress bar from a loop without the GIL.
#include "long_call.hpp"

#include <Python.h>

namespace tumble::python {

LongCall::LongCall(const py::object& progress, std::int64_t total, const std::string& unit)
    : m_total(total), m_nextPoll(Clock::now())
{
    if (progress.is_none()) {
        return;
    }
    if (PyBool_Check(progress.ptr())) {
        if (progress.cast<bool>()) {
            m_progress = py::module_::import("tumble._progress").attr("ProgressBar")(total, unit);
            m_ownBar = true;
        }
        return;
    }
    if (!PyCallable_Check(progress.ptr())) {
        throw py::type_error("progress must be True, False or a callable progress(done, total)");
    }
    m_progress = progress;
}

void LongCall::report(std::int64_t done)
{
    if (m_progress) {
        m_progress(done, m_total);
    }
}

bool LongCall::poll(std::int64_t done)
{
    if (m_error) {
        return true;
    }
    const Clock::time_point now = Clock::now();
    if (now < m_nextPoll) {
        return false;
    }
    m_nextPoll = now + std::chrono::duration_cast<Clock::duration>(
                           std::chrono::duration<double>(kPollSeconds));
    const py::gil_scoped_acquire gil;
    try {
        // a signal handler that raises (SIGINT: KeyboardInterrupt) leaves its exception set
        if (PyErr_CheckSignals() != 0) {
            throw py::error_already_set();
        }
        report(done);
    } catch (py::error_already_set& error) {
        m_error.emplace(std::move(error));
    }
    return m_error.has_value();
}

void LongCall::finish(std::int64_t done, const py::object& partial)
{
    if (!m_error) {
        report(done);
    }
    if (m_ownBar) {
        m_progress.attr("close")();
    }
    if (m_error) {
        // the partial result rides on the exception: `except KeyboardInterrupt as e: e.partial`
        if (!partial.is_none()) {
            if (PyObject_SetAttrString(m_error->value().ptr(), "partial", partial.ptr()) != 0) {
                PyErr_Clear();
            }
        }
        throw std::move(*m_error);
    }
}

} // namespace tumble::python
