/* Compile test: links two_static_copies_a.c and two_static_copies_b.c (each a FOVxx_STATIC
   copy of the libraries) into one program; both copies must render the same image. */
int two_static_copy_a(unsigned char *rgb, unsigned long *evals);
int two_static_copy_b(unsigned char *rgb, unsigned long *evals);

int main(void)
{
    static unsigned char a[8 * 6 * 3], b[8 * 6 * 3];
    unsigned long ea = 0, eb = 0;
    unsigned i;
    if (two_static_copy_a(a, &ea) != 0) return 1;
    if (two_static_copy_b(b, &eb) != 0) return 2;
    if (ea != eb) return 3;
    for (i = 0; i < sizeof a; i++)
        if (a[i] != b[i]) return 4;
    return 0;
}
