// README.md's first ```cpp block (Your first scene): a whole program, compiled as shown.
// @declarations
void usage() {
  // @statements
}
