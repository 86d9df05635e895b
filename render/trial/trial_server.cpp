#include "trial_server.h"

#include "offscreen.h"
#include "program_route.h"
#include "trial_wire.h"
#include "work_guard.h"

#include <cstdlib>
#include <memory>

namespace lb {

namespace {

bool readExactly(std::FILE *in, char *data, std::size_t size)
{
    return std::fread(data, 1, size, in) == size;
}

std::optional<QByteArray> readFrame(std::FILE *in)
{
    quint32 size = 0;
    if (!readExactly(in, reinterpret_cast<char *>(&size), sizeof size))
        return std::nullopt;
    QByteArray message(qsizetype(size), Qt::Uninitialized);
    if (!readExactly(in, message.data(), size))
        return std::nullopt;
    return message;
}

void send(std::FILE *out, const QByteArray &message)
{
    const QByteArray frame = trialwire::framed(message);
    std::fwrite(frame.constData(), 1, std::size_t(frame.size()), out);
    std::fflush(out);
}

trialwire::TryReply tryRequest(OffscreenRenderer &offscreen, const trialwire::TryRequest &r,
                               std::FILE *out)
{
    trialwire::TryReply reply;
    reply.id = r.id;
    // Compiled, linked and drawn under a memory bound: a program that makes the driver take
    // more ends this helper with kExitOutOfMemory, which the window turns into the refusal's
    // message (its time is the window's to bound: it kills a helper that does not answer).
    const WorkGuard guard(programMemoryKB(), 0, [](WorkGuard::Limit, long limitKB) {
        char limit[32];
        std::fprintf(stderr, "lightbench-trial: the driver took more than %s for this program\n",
                     memoryText(limitKB, limit));
        std::fflush(stderr);
        std::_Exit(trialwire::kExitOutOfMemory);
    });
    // The command line's sizes: this process may take its time, the window does not wait.
    const Scene scene = Scene::fromJson(r.scene);
    OffscreenProgramHost host(offscreen, scene);
    const ProgramVerdict verdict =
        buildAndTry(host, {r.vertex, r.fragment, scene.bindings}, {r.target, r.budgetMs},
                    [&](const ProgramBuild &build) {
                        // Built within bounds: the window may build it
                        // too while the frames are drawn here.
                        reply.diagnostics = build.diagnostics;
                        send(out, trialwire::encodeBuilt(reply));
                    });
    reply.diagnostics = verdict.build.diagnostics;
    reply.built = verdict.build.ok();
    if (verdict.trial)
        reply.result = *verdict.trial;
    return reply;
}

} // namespace

int runTrialServer(std::FILE *in, std::FILE *out)
{
    setDefaultGlFormat();
    OffscreenRenderer offscreen;
    if (const QString error = offscreen.initialize(QSize(64, 64)); !error.isEmpty()) {
        std::fprintf(stderr, "lightbench-trial: %s\n", qPrintable(error));
        return trialwire::kExitCannotDraw;
    }
    // Until the window sends its object: nothing but the background.
    offscreen.setObjectMesh(std::make_shared<Mesh>());
    while (const std::optional<QByteArray> frame = readFrame(in)) {
        const std::optional<trialwire::Decoded> message = trialwire::decode(*frame);
        if (!message) {
            std::fputs("lightbench-trial: a message this build does not know\n", stderr);
            return trialwire::kExitCannotDraw;
        }
        if (message->type == trialwire::Message::Mesh)
            offscreen.setObjectMesh(std::make_shared<Mesh>(message->mesh));
        else if (message->type == trialwire::Message::Try) {
            trialwire::TryReply reply = tryRequest(offscreen, message->request, out);
            if (offscreen.wasReset()) {
                // The driver reset the context while the program drew (a GPU's recovery):
                // refused, and this helper, whose context is gone, ends; another replaces it.
                reply.result.refusal =
                    refusalAt(message->request.vertex, message->request.fragment,
                              "the driver reset the OpenGL context while it tried this program: an "
                              "endless or very long loop?");
                send(out, trialwire::encodeReply(reply));
                return trialwire::kExitContextReset;
            }
            send(out, trialwire::encodeReply(reply));
        }
    }
    return 0;
}

} // namespace lb
