// Test fixture: ProgramCacheGLTest expects a compile error at line 4 of this file.
float brokenHelper() {
    float x = 1.0;
    return x +* 2.0;
}
