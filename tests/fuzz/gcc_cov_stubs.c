/* gcc's -fsanitize-coverage=trace-cmp also traces floating-point
 * comparisons, through two hooks libFuzzer does not define; the binary16
 * target (compiled by gcc, see the Makefile's fuzzing section) needs them to
 * link. They do nothing: libFuzzer's value profile uses the integer ones. */
void __sanitizer_cov_trace_cmpf(float a, float b);
void __sanitizer_cov_trace_cmpd(double a, double b);

void __sanitizer_cov_trace_cmpf(float a, float b)
{
    (void)a;
    (void)b;
}

void __sanitizer_cov_trace_cmpd(double a, double b)
{
    (void)a;
    (void)b;
}
