// What building a user's program says goes through Qt's translation system, whole (issue
// 31): with a translator that marks every text (marking_translator.h), each message of
// render/gl comes back as one marked sentence naming its stage, and the driver's own log lines
// are left as the driver wrote them. Bad sources tried: an empty vertex shader, an empty
// fragment shader, one over the size limit, a vertex shader with no position input, a
// fragment shader that writes no colour, one that does not compile, and an endless loop.

#include "dialect.h"
#include "marking_translator.h"
#include "reference_compare.h"

#include <QGuiApplication>
#include <QTest>

using namespace lb;
using namespace lb::test;

namespace {

const char *kVertex = "attribute vec4 vPosition;\n"
                      "void main() { gl_Position = vPosition; }\n";
const char *kFragment = "precision mediump float;\n"
                        "void main() { gl_FragColor = vec4(1.0); }\n";

QStringList messages(const ProgramBuild &build)
{
    QStringList out;
    for (const Diagnostic &d : build.diagnostics)
        out << d.message;
    return out;
}

} // namespace

class TestGlMessages : public QObject
{
    Q_OBJECT
private:
    OffscreenRenderer m_offscreen;

private slots:
    void initTestCase()
    {
        const QString error = m_offscreen.initialize(QSize(64, 64));
        QVERIFY2(error.isEmpty(), qPrintable(error));
    }

    void buildMessagesAreTranslatedWhole_data()
    {
        QTest::addColumn<QString>("vertex");
        QTest::addColumn<QString>("fragment");
        QTest::addColumn<QString>("expected");
        QTest::newRow("empty vertex") << QString() << QString(kFragment)
                                      << marked("lb::Program", "the vertex shader is empty");
        QTest::newRow("empty fragment") << QString(kVertex) << QString(" \n")
                                        << marked("lb::Program", "the fragment shader is empty");
        QTest::newRow("too big")
            << QString(kVertex) << QString(kFragment) + QString(kMaxSourceCharacters, ' ')
            << marked("lb::Program",
                      "the fragment shader is %1 KiB; lightbench compiles sources up to %2 KiB")
                   .arg((QString(kFragment).size() + kMaxSourceCharacters) / 1024)
                   .arg(kMaxSourceCharacters / 1024);
        QTest::newRow("no position")
            << QString("void main() { gl_Position = vec4(0.0); }\n") << QString(kFragment)
            << marked("lb::Program",
                      "no position input: the mesh reaches the shader through the attribute at "
                      "layout(location = 0), or one named aPos, a_position, vPosition, "
                      "aVertexPosition or position, or with pos or vert in its name");
        QTest::newRow("no colour")
            << QString(kVertex) << QString("precision mediump float;\nvoid main() {}\n")
            << marked("lb::Program", "the fragment shader writes no colour: assign gl_FragColor "
                                     "(no #version, #version 100) or declare an out vec4 "
                                     "(#version 300 es, 330 and later)");
        QTest::newRow("endless loop")
            << QString(kVertex)
            << QString("precision mediump float;\nvoid main() {\n  for (;;) {}\n"
                       "  gl_FragColor = vec4(1.0);\n}\n")
            << marked("lb::Loops", "this loop never ends: it has no condition and nothing in it "
                                   "breaks, returns or discards (the driver may drop it and "
                                   "draw garbage, or hang)");
    }

    void buildMessagesAreTranslatedWhole()
    {
        QFETCH(QString, vertex);
        QFETCH(QString, fragment);
        QFETCH(QString, expected);
        const MarkedMessages marks;
        const ProgramBuild build = m_offscreen.useProgram(vertex, fragment);
        QVERIFY2(messages(build).contains(expected), qPrintable(messages(build).join('\n')));
    }

    // The driver's log is its own: passed on as it is, only the workbench's words marked.
    void driverLinesAreLeftAsTheyAre()
    {
        const MarkedMessages marks;
        const ProgramBuild build = m_offscreen.useProgram(
            kVertex, "precision mediump float;\nvoid main() { gl_FragColor = vec4(x); }\n");
        QVERIFY(!build.ok());
        QVERIFY(!build.diagnostics.empty());
        for (const QString &m : messages(build))
            QVERIFY2(!m.contains(QChar(0x00ab)), qPrintable(m));
    }
};

int main(int argc, char **argv)
{
    setDefaultGlFormat();
    QGuiApplication app(argc, argv);
    TestGlMessages test;
    return QTest::qExec(&test, argc, argv);
}
#include "test_gl_messages.moc"
