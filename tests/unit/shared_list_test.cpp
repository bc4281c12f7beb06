// SharedList: a vector's behaviour, with copies that share every chunk a write left alone.
#include "core/shared_list.h"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace rs {
namespace {

using List = SharedList<std::string>;
constexpr std::size_t kChunk = List::kChunk;

List numbered(std::size_t n) {
    List l;
    for (std::size_t i = 0; i < n; ++i) l.push_back(std::to_string(i));
    return l;
}

void expectSame(const List& l, const std::vector<std::string>& want) {
    ASSERT_EQ(l.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) ASSERT_EQ(l[i], want[i]) << i;
    EXPECT_EQ(std::vector<std::string>(l.begin(), l.end()), want);
}

TEST(SharedList, ACopySharesEveryChunk_AndAWriteCopiesOnlyItsOwn) {
    const List a = numbered(10 * kChunk + 3);
    List b = a;
    ASSERT_EQ(b.chunkCount(), 11u);
    for (std::size_t c = 0; c < b.chunkCount(); ++c) EXPECT_TRUE(b.sharesChunk(a, c)) << c;
    b[4 * kChunk + 7] = "moved";
    for (std::size_t c = 0; c < b.chunkCount(); ++c) EXPECT_EQ(b.sharesChunk(a, c), c != 4) << c;
    EXPECT_EQ(a[4 * kChunk + 7], std::to_string(4 * kChunk + 7));  // The original is intact.
    EXPECT_EQ(b[4 * kChunk + 7], "moved");
    EXPECT_FALSE(a == b);
    b[4 * kChunk + 7] = a[4 * kChunk + 7];
    EXPECT_TRUE(a == b);  // Equal content in an unshared chunk is still equal.
    // A second write to the chunk it owns now copies nothing more.
    b[4 * kChunk + 8] = "again";
    EXPECT_FALSE(b.sharesChunk(a, 4));
    EXPECT_EQ(a[4 * kChunk + 8], std::to_string(4 * kChunk + 8));
}

TEST(SharedList, ReadingAConstCopyNeverCopiesAChunk) {
    const List a = numbered(3 * kChunk);
    const List b = a;
    std::size_t total = 0;
    for (const std::string& s : b) total += s.size();
    for (std::size_t i = 0; i < b.size(); ++i) total += b[i].size() + b.at(i).size();
    EXPECT_GT(total, 0u);
    for (std::size_t c = 0; c < b.chunkCount(); ++c) EXPECT_TRUE(b.sharesChunk(a, c));
}

TEST(SharedList, EditsBehaveAsAVectorsDo_AndLeaveTheCopyTheyCameFromAlone) {
    std::mt19937 rng(7);
    std::vector<std::string> want;
    List l;
    for (int step = 0; step < 3000; ++step) {
        const List before = l;
        const std::vector<std::string> wantBefore = want;
        const int op = int(rng() % 7);
        std::string v = "v";
        v += std::to_string(step);
        const std::size_t at = want.empty() ? 0 : rng() % want.size();
        if (op <= 1 || want.empty()) {
            l.push_back(v);
            want.push_back(v);
        } else if (op == 2) {
            l.insert(l.begin() + std::ptrdiff_t(at), v);
            want.insert(want.begin() + std::ptrdiff_t(at), v);
        } else if (op == 3) {
            l.erase(l.begin() + std::ptrdiff_t(at));
            want.erase(want.begin() + std::ptrdiff_t(at));
        } else if (op == 4) {
            l[at] = v;
            want[at] = v;
        } else if (op == 5) {
            l.pop_back();
            want.pop_back();
        } else {
            const char digit = char('0' + rng() % 10);
            auto pred = [&](const std::string& s) { return s.back() == digit; };
            const std::size_t n = l.eraseIf(pred);
            EXPECT_EQ(n, std::size_t(std::erase_if(want, pred)));
        }
        expectSame(l, want);
        expectSame(before, wantBefore);
    }
}

TEST(SharedList, EditableWritesEveryElement_AndClearEmpties) {
    const List a = numbered(2 * kChunk + 1);
    List b = a;
    for (std::string& s : b.editable()) s += '!';
    for (std::size_t i = 0; i < a.size(); ++i) {
        std::string want = std::to_string(i);
        want += '!';
        EXPECT_EQ(b[i], want);
        EXPECT_EQ(a[i], std::to_string(i));
    }
    b.clear();
    EXPECT_TRUE(b.empty());
    EXPECT_EQ(b.chunkCount(), 0u);
    EXPECT_EQ(a.size(), 2 * kChunk + 1);
    EXPECT_THROW((void)a.at(a.size()), std::out_of_range);
}

TEST(SharedList, CopiesWrittenOnTwoThreads_KeepTheirOwnElements) {
    const List base = numbered(4 * kChunk);
    List a = base, b = base;
    auto write = [](List& l, const std::string& tag) {
        for (int round = 0; round < 50; ++round) {
            List snapshot = l;  // Shares, then the write below copies again.
            std::string value = tag;
            value += std::to_string(round);
            for (std::size_t i = 0; i < l.size(); i += 17) l[i] = value;
        }
    };
    std::thread ta(write, std::ref(a), "a"), tb(write, std::ref(b), "b");
    ta.join();
    tb.join();
    for (std::size_t i = 0; i < base.size(); ++i) {
        EXPECT_EQ(base[i], std::to_string(i));
        EXPECT_EQ(a[i], i % 17 == 0 ? "a49" : std::to_string(i));
        EXPECT_EQ(b[i], i % 17 == 0 ? "b49" : std::to_string(i));
    }
}

}  // namespace
}  // namespace rs
