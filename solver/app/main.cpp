// ibms command line (placeholder until the Simulation lands).
int main() { return 0; }
