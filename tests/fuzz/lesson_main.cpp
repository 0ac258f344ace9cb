// The fuzz build's main for a lesson's program: the lesson's own main.cpp is
// compiled with main renamed to lesson_main (so that its command-line fuzz
// target can call it too), and this calls it. See rasterlab_lesson() in
// lessons/CMakeLists.txt.
int lesson_main(int argc, char** argv);

int main(int argc, char** argv) {
    return lesson_main(argc, argv);
}
