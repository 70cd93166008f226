// sim/HeapPolicy: once a large block is freed, blocks of a few MiB are still mapped from the system
// (and so given back to it when freed) rather than carved from the heap, where glibc's dynamic
// threshold would put them.
#include "sim/HeapPolicy.h"

#include <QTest>

#include <cstdlib>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#if defined(__SANITIZE_ADDRESS__)
#define VF_MALLOC_REPLACED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define VF_MALLOC_REPLACED 1
#endif
#endif

namespace {

// Through a volatile pointer, so that the compiler cannot pair and remove the allocations.
void* (*volatile allocate)(std::size_t) = std::malloc;

} // namespace

class TestHeapPolicy : public QObject {
    Q_OBJECT
private slots:
    void blocksOfAFewMegabytesStayMapped();
};

void TestHeapPolicy::blocksOfAFewMegabytesStayMapped()
{
#if !defined(__GLIBC__)
    QSKIP("the policy sets glibc's mmap threshold, and this C library is not glibc");
#elif defined(VF_MALLOC_REPLACED)
    QSKIP("AddressSanitizer replaces malloc, so glibc's mmap threshold does not apply");
#else
    vf::sim::keepLargeBlocksMapped();
    // Freeing an 8 MiB mapped block would raise glibc's dynamic threshold to 8 MiB.
    void* large = allocate(std::size_t(8) << 20);
    std::memset(large, 1, std::size_t(8) << 20);
    std::free(large);
    const std::size_t mappedBefore = mallinfo2().hblks;
    void* block = allocate(std::size_t(2) << 20);
    std::memset(block, 1, std::size_t(2) << 20);
    QCOMPARE(mallinfo2().hblks, mappedBefore + 1);
    std::free(block);
    QCOMPARE(mallinfo2().hblks, mappedBefore);
    // A small block still comes from the heap.
    void* small = allocate(std::size_t(64) << 10);
    QCOMPARE(mallinfo2().hblks, mappedBefore);
    std::free(small);
#endif
}

QTEST_APPLESS_MAIN(TestHeapPolicy)
#include "tst_heap_policy.moc"
