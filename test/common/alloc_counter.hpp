// Counting the heap allocations of a test binary, for the tests that check that a model's step
// does not allocate. test/common/alloc_counter.cpp replaces every form of the global operator
// new and delete (plain and array; aligned; nothrow; sized deletes) by malloc/free versions that
// count each allocation. It is linked only into the binaries registered with
// hbt_add_gtest(... COUNT_ALLOCATIONS) (root CMakeLists.txt): a binary that calls allocations()
// without it does not link.
#pragma once

namespace hbt::testing {

/// Calls of any form of the global operator new in this process so far (all threads).
long allocations();

}  // namespace hbt::testing
