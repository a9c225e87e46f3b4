// placeholder until the CLI lands (issue 9)
int main() { return 0; }
