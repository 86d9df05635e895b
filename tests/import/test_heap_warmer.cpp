// The headless run's heap warming (heap_warmer.h): what it touched while the event loop
// waited comes back, resident, to the next big allocation, which then touches its pages without
// faulting them in; a block taken beside it faults every page, so the count can tell.
#include "heap_warmer.h"

#include "allocator_tuning.h"
#include "resident_memory.h"

#include <QCoreApplication>
#include <QFile>
#include <QTest>

#include <cstdlib>
#include <cstring>

#include <sys/resource.h>
#include <unistd.h>

using namespace lb;

namespace {

long minorFaults()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_minflt;
}

// The page faults that writing every page of `bytes` of fresh allocation costs; the block is
// kept in `held` when given, freed otherwise.
long faultsToTouch(std::size_t bytes, void **held = nullptr)
{
    auto *block = static_cast<volatile char *>(std::malloc(bytes));
    const long before = minorFaults();
    for (std::size_t at = 0; at < bytes; at += std::size_t(sysconf(_SC_PAGESIZE)))
        block[at] = 1;
    const long faults = minorFaults() - before;
    if (held)
        *held = const_cast<char *>(block);
    else
        std::free(const_cast<char *>(block));
    return faults;
}

} // namespace

class TestHeapWarmer : public QObject
{
    Q_OBJECT

private slots:
    void warmedPagesComeBackWithoutFaults()
    {
#ifdef LIGHTBENCH_SANITIZE
        QSKIP("AddressSanitizer's allocator ignores glibc's settings");
#endif
        if (!platform::canTuneAllocator())
            QSKIP("this platform layer leaves the allocator as it comes: freed blocks go back");
        // With transparent huge pages always on, a fresh block faults 2 MB at a time: too few
        // faults for the count to tell warmed pages from new ones.
        QFile thp("/sys/kernel/mm/transparent_hugepage/enabled");
        if (thp.open(QIODevice::ReadOnly) && thp.readAll().contains("[always]"))
            QSKIP("transparent huge pages are always on: page faults cannot tell");
        constexpr std::size_t kBytes = 48u << 20;
        const long pages = long(kBytes / std::size_t(sysconf(_SC_PAGESIZE)));
        HeapWarmer warmer(kBytes);
        QTRY_COMPARE(warmer.warmedBytes(), kBytes); // in steps, from the event loop
        warmer.stop();
        void *held = nullptr;
        const long warmed = faultsToTouch(kBytes - (1u << 20), &held);
        QVERIFY2(warmed < pages / 50, qPrintable(QString("%1 faults").arg(warmed)));
        // The same size again while the warmed block is held: new pages, each faulted in.
        const long fresh = faultsToTouch(kBytes - (1u << 20));
        QVERIFY2(fresh > pages / 2, qPrintable(QString("%1 faults").arg(fresh)));
        std::free(held);
    }

    // A headless run gives the freed heap back once the mesh is in the driver's buffers, so
    // that the frame's memory comes on top of what is used, not of what was warmed.
    void givenBackTheFreedHeapLeaves()
    {
#ifdef LIGHTBENCH_SANITIZE
        QSKIP("AddressSanitizer's allocator ignores glibc's settings");
#endif
        if (!platform::canTuneAllocator() || residentKB() == 0)
            QSKIP("this platform layer leaves the allocator as it comes: freed blocks go back");
        constexpr std::size_t kBytes = 48u << 20;
        HeapWarmer warmer(kBytes);
        QTRY_COMPARE(warmer.warmedBytes(), kBytes);
        warmer.stop(); // freed, kept resident in the heap
        const long kept = residentKB();
        warmer.giveBack();
        const long left = residentKB();
        QVERIFY2(kept - left > long(kBytes >> 11), // more than half of it
                 qPrintable(QString("%1 KB resident, then %2 KB").arg(kept).arg(left)));
        HeapWarmer none(0); // nothing warmed: the allocator was not tuned, nothing to give
        none.giveBack();
    }

    void stoppedEarlyOrNeverStarted()
    {
        HeapWarmer none(0); // no mesh file: nothing to do
        QCOMPARE(none.warmedBytes(), std::size_t(0));
        none.stop();
        HeapWarmer partly(256u << 20);
        while (partly.warmedBytes() == 0) // one step for each pass of the event loop
            QCoreApplication::processEvents();
        partly.stop(); // mid-way: what was taken is freed, the steps end
        const std::size_t at = partly.warmedBytes();
        QTest::qWait(20);
        QCOMPARE(partly.warmedBytes(), at);
        QVERIFY(at < (256u << 20));
    }
};

QTEST_GUILESS_MAIN(TestHeapWarmer)
#include "test_heap_warmer.moc"
