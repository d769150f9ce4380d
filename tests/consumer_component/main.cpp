// Nothing to run: consumer_component only configures a target that links one component.
int main() { return 0; }
