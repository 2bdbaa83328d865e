// The error guard every command runs under and the "tumble: error:" and "tumble: warning:"
// lines (declared in console.hpp); apart from the printers so that the page (apps/web) can run
// the printers without the CLI's file and stream handling.
#include "console.hpp"

#include "cli_options.hpp"
#include "output_file.hpp"
#include "standard_output.hpp"

#include "tumble/scenario/scenario.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>

namespace tumble::cli {

void printError(const std::string& message)
{
    std::cout.flush();
    std::cerr << "tumble: error: " << message << std::endl;
}

void printWarning(const std::string& message)
{
    std::cout.flush();
    std::cerr << "tumble: warning: " << message << std::endl;
}

int runReportingErrors(const std::function<int()>& command)
{
    try {
        const int code = command();
        // Console output that could not be written (stdout on a full disk) is a failed run too.
        errno = 0;
        std::cout.flush();
        if (!std::cout || std::ferror(stdout) != 0) {
            const int error = standardOutputError() != 0 ? standardOutputError() : errno;
            printError(std::string("cannot write standard output: ") +
                       (error != 0 ? std::strerror(error) : "write error"));
            return code == kExitOk ? kExitWriteFailure : code;
        }
        return code;
    } catch (const OutputError& error) {
        printError(error.what());
        return kExitWriteFailure;
    } catch (const UsageError& error) {
        printError(error.what());
        return kExitBadInput;
    } catch (const scenario::ScenarioError& error) {
        printError(error.what());
        return kExitBadInput;
    } catch (const std::exception& error) {
        printError(error.what());
        return kExitFailure;
    } catch (...) {
        printError("unexpected failure");
        return kExitFailure;
    }
}

} // namespace tumble::cli
