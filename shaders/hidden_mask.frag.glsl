// The hidden-area mask: only the stencil is written (colour and ids masked).
void main() {}
