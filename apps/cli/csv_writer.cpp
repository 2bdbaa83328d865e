#include "csv_writer.hpp"

#include <stdexcept>
#include <system_error>

namespace tumble::cli {
namespace {

constexpr const char* kHeader =
    "time,body,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,kinetic,potential\n";

/// A name as one CSV field: quoted (with doubled quotes) only when it needs to be.
std::string csvField(const std::string& text)
{
    if (text.find_first_of(",\"\r\n") == std::string::npos) {
        return text;
    }
    std::string quoted = "\"";
    for (const char c : text) {
        quoted += c;
        if (c == '"') {
            quoted += '"';
        }
    }
    return quoted + "\"";
}

} // namespace

CsvWriter::CsvWriter(const std::string& path) : m_path(path), m_toStdout(path == "-")
{
    if (m_toStdout) {
        m_file = stdout;
    } else {
        m_temporary = std::filesystem::path(path + ".tmp");
        m_file = std::fopen(m_temporary.c_str(), "wb");
        if (m_file == nullptr) {
            throw std::runtime_error("cannot write " + m_temporary.string());
        }
    }
    std::fputs(kHeader, m_file);
}

CsvWriter::~CsvWriter()
{
    // an unfinished file is removed: only complete runs leave a CSV behind
    if (!m_toStdout && m_file != nullptr) {
        std::fclose(m_file);
        std::error_code ignored;
        std::filesystem::remove(m_temporary, ignored);
    }
}

void CsvWriter::writeSample(const scenario::Runner& runner)
{
    const Vec3& gravity = runner.world().settings().gravity;
    const Real time = runner.time();
    for (std::size_t i = 0; i < runner.bodies().size(); ++i) {
        const Body& body = runner.world().body(runner.bodies()[i]);
        const Vec3& x = body.position;
        const Quat& q = body.orientation;
        const Vec3& v = body.linearVelocity;
        const Vec3& w = body.angularVelocity;
        std::fprintf(m_file,
                     "%.17g,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,"
                     "%.17g,%.17g,%.17g,%.17g\n",
                     time, csvField(runner.bodyName(i)).c_str(), x.x, x.y, x.z, q.w, q.x, q.y, q.z,
                     v.x, v.y, v.z, w.x, w.y, w.z, body.kineticEnergy(),
                     body.potentialEnergy(gravity));
    }
}

void CsvWriter::finish()
{
    if (m_toStdout) {
        if (std::fflush(stdout) != 0) {
            throw std::runtime_error("cannot write the CSV to stdout");
        }
        return;
    }
    const bool failed = std::ferror(m_file) != 0;
    const bool closeFailed = std::fclose(m_file) != 0;
    m_file = nullptr;
    std::error_code error;
    if (failed || closeFailed) {
        std::filesystem::remove(m_temporary, error);
        throw std::runtime_error("cannot write " + m_temporary.string());
    }
    std::filesystem::rename(m_temporary, m_path, error);
    if (error) {
        std::filesystem::remove(m_temporary, error);
        throw std::runtime_error("cannot rename " + m_temporary.string() + " to " + m_path);
    }
}

} // namespace tumble::cli
