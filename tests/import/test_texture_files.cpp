// Image files as textures: read off the GUI thread through the object loader, each once, and
// refused with a message naming the file (missing, a folder, a pipe, not an image, a header
// claiming more than 16384 x 16384 texels, a truncated PNG) without changing the scene.
#include "object_loader.h"
#include "texture_file.h"

#include <QBuffer>
#include <QDir>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

using namespace lb;

namespace {

void write(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
        qFatal("cannot write %s", qPrintable(path));
}

struct Outcome
{
    bool ok = false;
    QString message;
};

// Opens `path` as the selected object's texture and waits for the loader's answer.
Outcome openTexture(ObjectLoader &loader, const QString &path)
{
    QSignalSpy finished(&loader, &ObjectLoader::textureFinished);
    loader.openTexture(path);
    if (finished.isEmpty() && !finished.wait(10000))
        return {false, "no answer"};
    return {finished.first().at(0).toBool(), finished.first().at(1).toString()};
}

} // namespace

class TestTextureFiles : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    QString m_good;

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QImage image(64, 32, QImage::Format_RGB32);
        image.fill(QColor(200, 40, 40));
        m_good = m_dir.filePath("red.png");
        QVERIFY(image.save(m_good));
    }

    void badFilesAreNamed_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("expected");
        QTest::newRow("missing") << "missing.png" << QByteArray() << "no such file";
        QTest::newRow("text named .png")
            << "notes.png" << QByteArray("uniform vec3 lightPosition;\n") << "not an image";
        QTest::newRow("empty") << "empty.jpg" << QByteArray("") << "an empty file, not an image";
        // A header's size is read before anything is decoded.
        QTest::newRow("20000 x 20000 header")
            << "huge.ppm" << QByteArray("P6\n20000 20000\n255\n") << "20000 x 20000 texels";
        QTest::newRow("17000 x 8 header")
            << "wide.ppm" << QByteArray("P6\n17000 8\n255\n") << "17000 x 8 texels";
        QImage image(16, 16, QImage::Format_RGB32);
        image.fill(Qt::blue);
        QByteArray png;
        {
            QBuffer buffer(&png);
            buffer.open(QIODevice::WriteOnly);
            image.save(&buffer, "PNG");
        }
        QTest::newRow("truncated PNG")
            << "cut.png" << png.left(png.size() / 2) << "could not be read as an image";
        // Each format's reader draws what it got and fills the rest grey or black (Qt says
        // nothing): a file that ends before its image does is refused.
        QImage photo(64, 48, QImage::Format_RGB32);
        for (int y = 0; y < photo.height(); ++y)
            for (int x = 0; x < photo.width(); ++x)
                photo.setPixel(x, y, qRgb(x * 4, y * 5, (x * y) & 255));
        for (const char *format : {"JPEG", "BMP", "GIF", "PPM", "TIFF", "WEBP"}) {
            QByteArray bytes;
            QBuffer buffer(&bytes);
            buffer.open(QIODevice::WriteOnly);
            if (!photo.save(&buffer, format))
                continue; // no plugin for it here
            const QString name = QString("cut.%1").arg(QString(format).toLower());
            QTest::newRow(qPrintable("truncated " + QString(format)))
                << name << bytes.left(bytes.size() * 2 / 3) << "could not be read as an image";
        }
    }

    void badFilesAreNamed()
    {
        QFETCH(QString, name);
        QFETCH(QByteArray, bytes);
        QFETCH(QString, expected);
        const QString path = m_dir.filePath(name);
        if (name != "missing.png")
            write(path, bytes);
        const TextureFileRead read = readTextureFile(path);
        QVERIFY(!read.texture);
        QVERIFY2(read.error.contains(name) && read.error.contains(expected),
                 qPrintable(read.error));

        // Through the loader: a message, and the scene as it was.
        SceneDocument document;
        document.edit([&](Scene &s) { s.objects[0].textureFile = m_good; });
        ObjectLoader loader(&document);
        QTRY_VERIFY(loader.texture());
        const Scene before = document.scene();
        const Outcome o = openTexture(loader, path);
        QVERIFY(!o.ok);
        QVERIFY2(o.message.contains(expected), qPrintable(o.message));
        QVERIFY(document.scene() == before);
        QCOMPARE(loader.texture()->image().size(), QSize(64, 32)); // still the red one
    }

    // The checks for a file cut short pass whole files: JPEG (with bytes after its end, as
    // some cameras write) and BMP, bottom-up and top-down.
    void wholeJpegsAndBitmapsAreRead()
    {
        QImage photo(40, 30, QImage::Format_RGB32);
        photo.fill(qRgb(200, 40, 10));
        for (const char *format : {"JPEG", "BMP"}) {
            QByteArray bytes;
            QBuffer buffer(&bytes);
            buffer.open(QIODevice::WriteOnly);
            QVERIFY(photo.save(&buffer, format));
            if (QByteArray(format) == "JPEG")
                bytes += QByteArray(100, 'x');
            const QString path = m_dir.filePath(QString("whole.%1").arg(format).toLower());
            write(path, bytes);
            const TextureFileRead read = readTextureFile(path);
            QVERIFY2(read.texture, qPrintable(read.error));
            QCOMPARE(read.texture->image().size(), QSize(40, 30));
        }
    }

    void aFolderAndAPipeAreNoImages()
    {
        QVERIFY(QDir(m_dir.path()).mkpath("folder.png"));
        QVERIFY(readTextureFile(m_dir.filePath("folder.png")).error.contains("not a regular file"));
        const QString fifo = m_dir.filePath("pipe.png");
        QCOMPARE(mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        QVERIFY(readTextureFile(fifo).error.contains("not a regular file"));
    }

    void anImageBecomesTheSelectedObjectsTexture()
    {
        SceneDocument document;
        document.edit([](Scene &s) {
            s.objects.resize(2);
            s.selected = 1;
        });
        ObjectLoader loader(&document);
        QSignalSpy drawn(&loader, &ObjectLoader::meshReady);
        const Outcome o = openTexture(loader, m_good);
        QVERIFY2(o.ok, qPrintable(o.message));
        QVERIFY2(o.message.contains("red.png: 64 x 32 texels"), qPrintable(o.message));
        const ObjectSettings &object = document.scene().objects[1];
        QCOMPARE(object.textureFile, m_good);
        QVERIFY(object.texture); // switched on
        QVERIFY(document.scene().objects[0].textureFile.isEmpty());
        QVERIFY(loader.texture(1) && !loader.texture(0)); // object 0 keeps the checker
        // The view was told.
        QVERIFY(std::any_of(drawn.begin(), drawn.end(), [&](const QList<QVariant> &args) {
            return args.at(0).toInt() == 1 &&
                   args.at(2).value<std::shared_ptr<const Texture>>() == loader.texture(1);
        }));
        // Another object naming the same file shares the one decoded image.
        document.edit([&](Scene &s) { s.objects[0].textureFile = m_good; });
        QCOMPARE(loader.texture(0), loader.texture(1));
        // "None" goes back to the checker.
        document.edit([](Scene &s) { s.objects[1].textureFile.clear(); });
        QVERIFY(!loader.texture(1));
    }

    // Opened again after it changed on disk (a student repainted it), the image is read
    // again; the old one draws until the new one is in.
    void anImageOpenedAgainIsReadAgain()
    {
        const QString path = m_dir.filePath("repainted.png");
        QImage image(8, 8, QImage::Format_RGB32);
        image.fill(QColor(255, 0, 0));
        QVERIFY(image.save(path));
        SceneDocument document;
        ObjectLoader loader(&document);
        QVERIFY(openTexture(loader, path).ok);
        const std::shared_ptr<const Texture> red = loader.texture(0);
        image.fill(QColor(0, 255, 0));
        QVERIFY(image.save(path));
        loader.openTexture(path);
        QCOMPARE(loader.texture(0), red); // still drawn meanwhile
        QTRY_VERIFY(loader.texture(0) != red);
        QCOMPARE(qGreen(loader.texture(0)->image().pixel(0, 0)), 255);
    }

    // Two images opened for two objects before either is in: each gets its own.
    void twoOpensBeforeEitherIsIn()
    {
        const QString blue = m_dir.filePath("blue.png");
        QImage image(4, 4, QImage::Format_RGB32);
        image.fill(Qt::blue);
        QVERIFY(image.save(blue));
        SceneDocument document;
        document.edit([](Scene &s) { s.objects.resize(2); });
        ObjectLoader loader(&document);
        QSignalSpy finished(&loader, &ObjectLoader::textureFinished);
        loader.openTexture(m_good);
        document.edit([](Scene &s) { s.selected = 1; });
        loader.openTexture(blue);
        QTRY_COMPARE(finished.size(), 2);
        QCOMPARE(document.scene().objects[0].textureFile, m_good);
        QCOMPARE(document.scene().objects[1].textureFile, blue);
    }

    // A thin image (a toon ramp) wider than a texture may be is scaled to 4096 x 1, not
    // refused.
    void aThinWideRampIsScaledNotRefused()
    {
        QImage ramp(5000, 1, QImage::Format_RGB32);
        for (int x = 0; x < ramp.width(); ++x)
            ramp.setPixel(x, 0, qRgb(x * 255 / 4999, 0, 0));
        const QString path = m_dir.filePath("ramp.png");
        QVERIFY(ramp.save(path));
        const TextureFileRead read = readTextureFile(path);
        QVERIFY2(read.texture, qPrintable(read.error));
        QCOMPARE(read.texture->image().size(), QSize(4096, 1));
        QVERIFY2(read.summary.contains("scaled from 5000 x 1"), qPrintable(read.summary));
    }

    // A scene (a file, a restart) naming an image that is gone: a message, and those objects
    // show the checker; the rest of the scene is untouched.
    void aSceneNamingAMissingImage()
    {
        SceneDocument document;
        document.edit([&](Scene &s) {
            s.objects.resize(2);
            s.objects[0].textureFile = m_dir.filePath("gone.png");
            s.objects[0].texture = true;
            s.objects[1].textureFile = m_good;
        });
        QSignalSpy finished(&document, &SceneDocument::changed);
        ObjectLoader loader(&document);
        QSignalSpy messages(&loader, &ObjectLoader::textureFinished);
        QTRY_VERIFY(!messages.isEmpty());
        QVERIFY(!messages.first().at(0).toBool());
        QVERIFY(messages.first().at(1).toString().contains("gone.png: no such file"));
        QTRY_VERIFY(loader.texture(1));
        // The object keeps naming it (a scene saved now loses nothing) and shows the checker.
        const QString gone = m_dir.filePath("gone.png");
        QCOMPARE(document.scene().objects[0].textureFile, gone);
        QVERIFY(!loader.texture(0));
        QVERIFY(loader.textureProblem(0).contains("no such file"));
        QVERIFY(document.scene().objects[0].texture);
        QCOMPARE(document.scene().objects[1].textureFile, m_good);
        // Not tried again on every change while it is still missing; read once it is back.
        messages.clear();
        document.edit([](Scene &s) { s.objects[1].rotationDegrees.y = 10; });
        QTest::qWait(50);
        QVERIFY(messages.isEmpty());
        QVERIFY(QFile::copy(m_good, gone));
        document.edit([](Scene &s) { s.objects[1].rotationDegrees.y = 20; });
        QTRY_VERIFY(loader.texture(0));
        QVERIFY(loader.textureProblem(0).isEmpty());
    }

    // The image opened for an object that is removed before it is in is not put on another.
    void removingTheObjectWhileItsImageIsRead()
    {
        SceneDocument document;
        document.edit([](Scene &s) {
            s.objects.resize(3);
            s.selected = 2;
        });
        ObjectLoader loader(&document);
        QSignalSpy finished(&loader, &ObjectLoader::textureFinished);
        loader.openTexture(m_good);
        // A material edit before the removal does not make the loader blame the wrong object.
        document.edit([](Scene &s) { s.objects[0].material.shininess = 3; });
        document.edit([](Scene &s) {
            s.objects.pop_back();
            s.selected = 0;
        });
        QTRY_VERIFY(!finished.isEmpty());
        QVERIFY(!finished.first().at(0).toBool());
        QVERIFY2(finished.first().at(1).toString().contains("its object was removed"),
                 qPrintable(finished.first().at(1).toString()));
        for (const ObjectSettings &o : document.scene().objects)
            QVERIFY(o.textureFile.isEmpty());

        // The same after a material edit, for an object before it: the image follows its object.
        finished.clear();
        document.edit([](Scene &s) {
            s.objects.resize(3);
            s.selected = 2;
        });
        loader.openTexture(m_good);
        document.edit([](Scene &s) { s.objects[1].material.shininess = 9; });
        document.edit([](Scene &s) {
            s.objects.erase(s.objects.begin());
            s.selected = 0;
        });
        QTRY_VERIFY(!finished.isEmpty());
        QVERIFY2(finished.first().at(0).toBool(), qPrintable(finished.first().at(1).toString()));
        QCOMPARE(document.scene().objects[1].textureFile, m_good);
        QVERIFY(document.scene().objects[0].textureFile.isEmpty());
    }
};

QTEST_MAIN(TestTextureFiles)
#include "test_texture_files.moc"
