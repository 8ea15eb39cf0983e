// The text of path files (walk, plan, bench and preview --path): a number
// with two signs is refused at its field, a UTF-8 byte order mark is read
// past, UTF-16 text and a file without poses are refused in one line each.
#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

class HostilePathFileText : public Hostile {};

TEST_F(HostilePathFileText, TwoSignsBomsWideTextOrNoPoses) {
    spit(dir_ / "signs.txt", "+-0.3 1.6 1 0 0 0\n");
    expect_refused(run("$BIN walk lay.json --path signs.txt"), 1, "signs.txt:1: X: '+-0.3' is not a finite number");
    spit(dir_ / "bom.txt",
         "\xEF\xBB\xBF"
         "0 1.6 1 0 0 0\n");
    const Outcome bom = run("$BIN walk lay.json --path bom.txt");
    EXPECT_EQ(bom.status, 0) << bom.err;
    EXPECT_NE(bom.out.find("\"frame\":0"), std::string::npos) << bom.out;
    spit(dir_ / "wide.txt", std::string("\xFF\xFE"
                                        "0\0 \0"
                                        "1\0\n\0",
                                        10));
    for (const char* command : {"walk lay.json --path", "plan lay.json --out p.svg --path", "bench lay.json --path"})
        expect_refused(run(std::string("$BIN ") + command + " wide.txt"), 1,
                       "wide.txt: is UTF-16 text; save it as UTF-8 or ASCII");
    spit(dir_ / "none.txt", "# only a comment\n\n");
    for (const char* command : {"walk lay.json --path", "plan lay.json --out p.svg --path", "bench lay.json --path"})
        expect_refused(run(std::string("$BIN ") + command + " none.txt"), 1, "none.txt: the path file holds no poses");
    expect_refused(run("$BIN preview lay.json --path none.txt --frames 1 --screenshots shots"), 1,
                   "none.txt: the path file holds no poses");
    EXPECT_FALSE(fs::exists(dir_ / "p.svg"));
}

}  // namespace
}  // namespace impossible::hostile
