// A valid shared library that exports no gsModuleDescriptor.
extern "C" __attribute__((visibility("default"))) int notAModuleAnswer() {
    return 42;
}
