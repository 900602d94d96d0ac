/// @file test_proof_journal.cpp
/// @brief The --state directory's journal lines and checkpoints: written and
/// read back, and every single-bit change of them refused.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/checksum.hpp"
#include "io/error.hpp"
#include "primes/proof_journal_format.hpp"

namespace {

using namespace tk::primes;

bool same(const JournalEntry& a, const JournalEntry& b) {
  return a.key == b.key && a.output == b.output && a.log_offset == b.log_offset && a.log_lines == b.log_lines;
}

const JournalEntry kPrime{
    R"(start=llr {"k":3,"b":2,"n":391,"c":-1,"id":"x"})",
    R"({"k":3,"b":2,"n":391,"c":-1,"id":"x","verdict":"prime","test":"llr","P":3,"seconds":0.03})",
    0,
    {"3*2^391-1 is prime! (119 decimal digits)  Time : 0.030 sec."}};
const JournalEntry kForm{
    R"(start=d13 {"k":3,"n":2,"form":"cc1","length":2})",
    R"({"k":3,"n":2,"form":"cc1","length":2,"verdict":"composite","test":"trial","seconds":1e-05,)"
    R"("members":[{"n":2,"c":-1,"verdict":"prime","test":"trial"},{"n":3,"c":-1,"verdict":"composite","test":"trial","witness":"factor 23"}]})",
    60,
    {"3*2^2-1 is prime! (2 decimal digits)  Time : 0.000 sec.", "3*2^3-1 is not prime.  factor 23  Time : 0.000 sec."}};

TEST(ProofJournal, LinesReadBackAsWritten) {
  for (const JournalEntry& entry : {kPrime, kForm}) EXPECT_TRUE(same(parse_journal_line(journal_line(entry)), entry));
  const JournalText journal = read_journal(journal_line(kPrime) + "\n" + journal_line(kForm) + "\n");
  ASSERT_EQ(journal.entries.size(), 2u);
  EXPECT_TRUE(journal.refused.empty());
}

TEST(ProofJournal, EveryFlippedBitIsRefusedNeverReadAsAnotherRecord) {
  const std::string first = journal_line(kPrime) + "\n", text = first + journal_line(kForm) + "\n";
  for (std::size_t position = 0; position < text.size(); ++position)
    for (int bit = 0; bit < 8; ++bit) {
      std::string damaged = text;
      damaged[position] = static_cast<char>(damaged[position] ^ (1 << bit));
      const JournalText journal = read_journal(damaged);
      // Only the undamaged line comes back (a flipped newline merges or tears lines: neither does).
      const JournalEntry& intact = position < first.size() ? kForm : kPrime;
      for (const JournalEntry& entry : journal.entries)
        EXPECT_TRUE(same(entry, intact)) << "position " << position << " bit " << bit;
      EXPECT_LE(journal.entries.size(), 1u) << "position " << position << " bit " << bit;
    }
}

TEST(ProofJournal, RefusedLinesSayWhy) {
  const auto why = [](const std::string& line) {
    try {
      parse_journal_line(line);
    } catch (const tk::Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(why(kPrime.key + "\t" + kPrime.output), "has no checksum (written by an older riesel)");
  EXPECT_EQ(why("a\tb\tc"), "has 3 fields, not 5");
  std::string line = journal_line(kPrime);
  line[line.size() - 1] = line[line.size() - 1] == '0' ? '1' : '0';
  EXPECT_EQ(why(line), "fails its checksum");
  // Checksums that match, fields that do not: each is refused all the same.
  const auto with = [](JournalEntry entry, auto change) {
    change(entry);
    return journal_line(entry);
  };
  EXPECT_EQ(why(with(kPrime, [](JournalEntry& e) { e.key = "start=xyz {}"; })), "holds no valid key");
  EXPECT_EQ(why(with(kPrime, [](JournalEntry& e) { e.output.replace(e.output.find("prime"), 5, "psime"); })),
            "holds no valid verdict");
  EXPECT_EQ(why(with(kPrime, [](JournalEntry& e) { e.output.replace(e.output.find("391"), 3, "393"); })),
            "holds the output of another record");
  EXPECT_EQ(why(with(kPrime, [](JournalEntry& e) { e.log_lines = {"a\nb"}; })), "holds no valid lresults.txt lines");
}

TEST(ProofJournal, ATornLastLineIsNeitherReadNorCounted) {
  const std::string whole = journal_line(kPrime) + "\n", torn = journal_line(kForm).substr(0, 40);
  const JournalText journal = read_journal(whole + torn);
  EXPECT_EQ(journal.entries.size(), 1u);
  EXPECT_TRUE(journal.refused.empty());
  EXPECT_EQ(journal.whole_bytes, whole.size());
}

TEST(ProofJournal, LogCompletionAddsOnlyWhatIsMissing) {
  const std::string all = log_text(kForm);
  EXPECT_EQ(log_completion("", kForm), all);
  EXPECT_EQ(log_completion(all.substr(0, 10), kForm), all.substr(10));
  EXPECT_EQ(log_completion(all, kForm), std::nullopt);               // all there
  EXPECT_EQ(log_completion("something else", kForm), std::nullopt);  // not this record's lines
}

TEST(ProofJournal, CheckpointsReadBackAndEveryFlippedBitIsRefused) {
  const std::string member = "3*2^391-1 start=llr";
  const ProofState state{1000, mpz_class("123456789abcdef0123", 16)};
  const std::string text = checkpoint_text(member, state);
  const ProofState back = parse_checkpoint(text, member);
  EXPECT_EQ(back.iteration, state.iteration);
  EXPECT_EQ(back.value, state.value);
  EXPECT_THROW(parse_checkpoint(text, "3*2^393-1 start=llr"), tk::Error);
  for (std::size_t position = 0; position < text.size(); ++position)
    for (int bit = 0; bit < 8; ++bit) {
      std::string damaged = text;
      damaged[position] = static_cast<char>(damaged[position] ^ (1 << bit));
      EXPECT_THROW(parse_checkpoint(damaged, member), tk::Error) << "position " << position << " bit " << bit;
    }
}

TEST(ProofJournal, CheckpointFieldsMustBeWrittenAsRieselWritesThem) {
  const std::string member = "3*2^391-1 start=llr";
  // Valid checksums, fields no riesel writes: a sign, blanks, upper case, leading zeros, overflow.
  const auto crafted = [&](const std::string& iteration, const std::string& residue) {
    const std::string text = "riesel-checkpoint 1\n" + member + "\n" + iteration + "\n" + residue + "\n";
    return text + fmt::format("{:016x}\n", tk::io::fnv1a(text));
  };
  EXPECT_NO_THROW(parse_checkpoint(crafted("99999999", "5"), member));  // a syntax the proof itself refuses
  for (const auto& [iteration, residue] :
       std::vector<std::pair<std::string, std::string>>{{"-5", "5"},
                                                        {" 5", "5"},
                                                        {"00000000", "5"},
                                                        {"05", "5"},
                                                        {"5x", "5"},
                                                        {"", "5"},
                                                        {"18446744073709551616", "5"},
                                                        {"5", "-5"},
                                                        {"5", "AB"},
                                                        {"5", "05"},
                                                        {"5", " 5"},
                                                        {"5", ""}})
    EXPECT_THROW(parse_checkpoint(crafted(iteration, residue), member), tk::Error) << iteration << " / " << residue;
}

}  // namespace
