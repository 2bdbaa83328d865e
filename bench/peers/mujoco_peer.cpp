// MuJoCo peer: an MJCF model built in memory (free-joint boxes over a plane) stepped with mj_step
// at MuJoCo's default solver settings. MuJoCo 2.2 has no sleeping and no exact restitution; both
// are stated in the settings line.

#include "peer_detail.hpp"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <limits>
#include <locale>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace tumble::bench::detail {
namespace {

// Sized for every body lying on one face (4 box-plane contacts); MuJoCo 2.2 preallocates all of its
// contact and constraint storage from these, so they cannot grow while stepping. Overflow (piles of
// boxes touching each other) is counted by MuJoCo as a warning, which the settings line reports.
constexpr int kContactsPerBody = 4;
// A pyramidal friction cone with condim 3 takes 4 constraint rows per contact.
constexpr int kRowsPerContact = 4;
// MuJoCo's default contact time constant; it must stay at least two steps long to be stable.
constexpr double kDefaultTimeConstant = 0.02;

// The damping ratio of a mass-spring contact whose bounce keeps a fraction e of the approach speed:
// e = exp(-zeta pi / sqrt(1 - zeta^2)). e = 0 gives critical damping, MuJoCo's default.
double dampingRatio(double restitution) {
    if (restitution <= 0.0) {
        return 1.0;
    }
    if (restitution >= 1.0) {
        return 0.0;
    }
    const double logE = -std::log(restitution);
    return logE / std::sqrt(std::numbers::pi * std::numbers::pi + logE * logE);
}

// Restitution goes into the damping alone: with a negative solref MuJoCo takes stiffness and
// damping directly, and k = 1/tc^2, b = 2 zeta/tc reproduce its default solref (tc, 1) when zeta
// = 1.
struct ContactSprings {
    double timeConstant;
    double stiffness() const { return 1.0 / (timeConstant * timeConstant); }
    double damping(double restitution) const {
        return 2.0 * dampingRatio(restitution) / timeConstant;
    }
};

// The ground plane's normal is its local +z; a -90 degree turn about x makes it the world's +y,
// so the whole model stays y-up and nothing needs converting on the way in or out.
std::string modelXml(const PeerScene& scene, const ContactSprings& springs, int nconmax,
                     int njmax) {
    std::ostringstream xml;
    xml.imbue(std::locale::classic());
    xml.precision(17);
    xml << "<mujoco model=\"tumble_peer\">\n"
        << "  <size nconmax=\"" << nconmax << "\" njmax=\"" << njmax << "\"/>\n"
        << "  <option timestep=\"" << scene.dt << "\" gravity=\"" << scene.gravity[0] << ' '
        << scene.gravity[1] << ' ' << scene.gravity[2] << "\"/>\n"
        << "  <worldbody>\n"
        << "    <geom name=\"ground\" type=\"plane\" size=\"0 0 1\" pos=\"0 " << scene.groundHeight
        << " 0\" quat=\"" << std::sqrt(0.5) << ' ' << -std::sqrt(0.5) << " 0 0\"/>\n";
    for (const PeerBody& body : scene.bodies) {
        // Negative solref gives stiffness and damping directly, so restitution only changes the
        // damping; priority 1 makes a body's own material win over the ground's in a contact.
        xml << "    <body pos=\"" << body.position[0] << ' ' << body.position[1] << ' '
            << body.position[2] << "\" quat=\"" << body.orientation[0] << ' ' << body.orientation[1]
            << ' ' << body.orientation[2] << ' ' << body.orientation[3] << "\">\n"
            << "      <freejoint/>\n"
            << "      <geom type=\"box\" size=\"" << body.size[0] / 2 << ' ' << body.size[1] / 2
            << ' ' << body.size[2] / 2 << "\" mass=\"" << body.mass << "\" friction=\""
            << body.friction << " 0.005 0.0001\" priority=\"1\" solref=\"" << -springs.stiffness()
            << ' ' << -springs.damping(body.restitution) << "\"/>\n"
            << "    </body>\n";
    }
    xml << "  </worldbody>\n</mujoco>\n";
    return xml.str();
}

struct Vfs {
    std::unique_ptr<mjVFS> vfs =
        std::make_unique<mjVFS>(); // ~2 MB of name tables: not on the stack
    Vfs() { mj_defaultVFS(vfs.get()); }
    Vfs(const Vfs&) = delete;
    Vfs& operator=(const Vfs&) = delete;
    ~Vfs() { mj_deleteVFS(vfs.get()); }
};

struct MujocoWorld {
    mjModel* model = nullptr;
    mjData* data = nullptr;
    MujocoWorld() = default;
    MujocoWorld(const MujocoWorld&) = delete;
    MujocoWorld& operator=(const MujocoWorld&) = delete;
    ~MujocoWorld() {
        if (data) {
            mj_deleteData(data);
        }
        if (model) {
            mj_deleteModel(model);
        }
    }
};

// MuJoCo 2.2 sizes mjData once, from njmax: dense njmax x nv Jacobians (values and column indices,
// plain and transposed) and an njmax x njmax matrix with its indices, all in one buffer whose size
// is an int, so the buffer cannot exceed 2 GiB. A failed allocation in mj_makeData exits the
// process, so scenes that cannot fit are refused up front with this (slight under-)estimate.
void checkDataFits(long long nv, long long njmax) {
    const long long bytes = njmax * nv * 2 * static_cast<long long>(sizeof(mjtNum) + sizeof(int)) +
                            njmax * njmax * static_cast<long long>(sizeof(mjtNum) + sizeof(int));
    const long long physical =
        static_cast<long long>(sysconf(_SC_PHYS_PAGES)) * sysconf(_SC_PAGESIZE);
    const long long limit = std::min<long long>(std::numeric_limits<int>::max(),
                                                physical > 0 ? physical / 2 : LLONG_MAX);
    if (bytes > limit) {
        throw PeerCapacityError(
            "MuJoCo 2.2 preallocates dense constraint storage: nv " + std::to_string(nv) +
            " with njmax " + std::to_string(njmax) + " needs about " + std::to_string(bytes >> 20) +
            " MiB in one mjData buffer, above its " + std::to_string(limit >> 20) +
            " MiB limit (2 GiB int-sized buffer, or half of RAM)");
    }
}

void setVelocities(const mjModel* m, mjData* d, const PeerScene& scene) {
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const PeerBody& body = scene.bodies[i];
        const int joint = m->body_jntadr[i + 1]; // body 0 is the world
        mjtNum* qvel = d->qvel + m->jnt_dofadr[joint];
        const mjtNum* quat = d->qpos + m->jnt_qposadr[joint] + 3;
        // A free joint's angular velocity is in the body frame; rotate the world one back into it.
        mjtNum inverse[4];
        mju_negQuat(inverse, quat);
        const mjtNum world[3] = {body.angularVelocity[0], body.angularVelocity[1],
                                 body.angularVelocity[2]};
        for (int k = 0; k < 3; ++k) {
            qvel[k] = body.velocity[k];
        }
        mju_rotVecQuat(qvel + 3, world, inverse);
    }
}

const char* solverName(int solver) {
    switch (solver) {
    case mjSOL_PGS: return "PGS";
    case mjSOL_CG: return "CG";
    case mjSOL_NEWTON: return "Newton";
    default: return "unknown";
    }
}

std::string describe(const mjModel* m, const mjData* d, const ContactSprings& springs) {
    std::ostringstream out;
    out << solverName(m->opt.solver) << " solver, at most " << m->opt.iterations
        << " iterations, tolerance " << m->opt.tolerance << ", "
        << (m->opt.integrator == mjINT_EULER ? "semi-implicit Euler" : "non-Euler") << ", "
        << (m->opt.cone == mjCONE_PYRAMIDAL ? "pyramidal" : "elliptic") << " cone, "
        << (m->opt.jacobian == mjJAC_AUTO ? "auto (sparse for nv >= 60)" : "fixed")
        << " Jacobian, nconmax " << m->nconmax << ", njmax " << m->njmax
        << " (preallocated: dense njmax x nv and njmax x njmax arrays, and a stack of " << m->nstack
        << " mjtNums, mostly never touched but counted in heapBytes); soft contacts: no exact "
        << "Newton restitution, restitution e mapped to a mass-spring-damper contact with solref "
        << "(-k, -b), k = 1/tc^2, b = 2 zeta/tc, zeta = -ln e / sqrt(pi^2 + ln^2 e), tc "
        << springs.timeConstant << " s, default solimp; body material wins over the ground "
        << "(priority), body-body friction max and solref averaged; no sleeping in MuJoCo 2.2: at "
        << "rest means |v|, |w| < " << kAtRestSpeed;
    for (int i = 0; i < mjNWARNING; ++i) {
        if (d->warning[i].number > 0) {
            out << "; WARNING x" << d->warning[i].number << ": "
                << mju_warningText(i, d->warning[i].lastinfo);
        }
    }
    return out.str();
}

} // namespace

std::string mujocoName() {
    const int version = mj_version();
    return "MuJoCo " + std::to_string(version / 100) + "." + std::to_string(version / 10 % 10) +
           "." + std::to_string(version % 10);
}

PeerResult runMujoco(const PeerScene& scene) {
    PeerResult result;
    result.engine = mujocoName();

    const int bodies = static_cast<int>(scene.bodies.size());
    const int nconmax = kContactsPerBody * bodies + 16;
    const int njmax = kRowsPerContact * nconmax;
    checkDataFits(6LL * bodies, njmax);

    const ContactSprings springs{std::max(kDefaultTimeConstant, 2.0 * scene.dt)};
    const std::string xml = modelXml(scene, springs, nconmax, njmax);
    const char* fileName = "tumble_peer.xml";
    Vfs vfs;
    if (mj_makeEmptyFileVFS(vfs.vfs.get(), fileName, static_cast<int>(xml.size())) != 0) {
        throw std::runtime_error("MuJoCo: could not make the in-memory model file");
    }
    std::memcpy(vfs.vfs->filedata[mj_findFileVFS(vfs.vfs.get(), fileName)], xml.data(), xml.size());

    const long long heapBefore = heapInUse();
    MujocoWorld world;
    char error[1000] = "";
    world.model = mj_loadXML(fileName, vfs.vfs.get(), error, sizeof error);
    if (!world.model) {
        // The compiler makes a trial mjData; failing that is the same capacity limit as above.
        const std::string message = std::string("MuJoCo rejected the model: ") + error;
        if (message.find("could not create mjData") != std::string::npos) {
            throw PeerCapacityError(message);
        }
        throw std::runtime_error(message);
    }
    // The parser keeps a copy of the last model for mj_saveLastXML; an application would free it.
    mj_freeLastXML();
    world.data = mj_makeData(world.model);
    setVelocities(world.model, world.data, scene);
    result.heapBytes = heapInUse() - heapBefore;

    result.stepSeconds = timeSteps(scene.steps, [&] { mj_step(world.model, world.data); });
    result.heapBytesAtEnd = heapInUse() - heapBefore;

    const mjModel* m = world.model;
    const mjData* d = world.data;
    result.finalPositions.reserve(scene.bodies.size());
    for (int i = 0; i < bodies; ++i) {
        const int joint = m->body_jntadr[i + 1];
        const mjtNum* qpos = d->qpos + m->jnt_qposadr[joint];
        const mjtNum* qvel = d->qvel + m->jnt_dofadr[joint];
        if (slowerThanRest(qvel, qvel + 3)) {
            ++result.bodiesAtRest;
        }
        result.finalPositions.push_back({qpos[0], qpos[1], qpos[2]});
    }
    result.settings = describe(m, d, springs);
    return result;
}

} // namespace tumble::bench::detail
