# Golden values for analysis/wilcoxon (tests/analysis/stats/test_wilcoxon.cpp): R's wilcox.test(x, y,
# paired = TRUE, ...) on seeded samples covering the exact distribution (two-sided, greater, less),
# the normal approximation (n >= 50, exact = FALSE, ties, zeros, with and without continuity
# correction), and binom.test for the sign test. Run from this folder: Rscript make_golden.R
set.seed(45)
g17 <- function(x) sprintf("%.17g", x)
cases <- list()
add <- function(name, x, y, alternative = "two.sided", exact = NULL, correct = TRUE) {
  cases[[length(cases) + 1]] <<- list(name = name, x = x, y = y, alternative = alternative,
                                      exact = exact, correct = correct)
}
add("exact10", round(rnorm(10, 1, 2), 3), round(rnorm(10), 3))
add("exact12_greater", round(rnorm(12, 0.8), 3), round(rnorm(12), 3), alternative = "greater")
add("exact7_less", round(rnorm(7, -0.5), 3), round(rnorm(7), 3), alternative = "less")
add("exact20_tail", round(rnorm(20, 1.5), 3), round(rnorm(20), 3))
add("normal60", round(rnorm(60, 0.3), 4), round(rnorm(60), 4))
add("forced_normal15", round(rnorm(15, 0.5), 3), round(rnorm(15), 3), exact = FALSE)
add("ties_ints", c(5, 7, 3, 9, 8, 6, 4, 10, 7), c(3, 5, 4, 6, 5, 8, 2, 6, 4))
add("zeros_ties_nocorrect", c(3, 3, 7, 2, 9, 4, 6, 8), c(3, 1, 4, 2, 5, 2, 6, 3), correct = FALSE)
add("ties_greater", c(12, 15, 11, 14, 18, 13, 16, 20, 13, 17), c(10, 12, 11, 15, 14, 10, 13, 15, 11, 12),
    alternative = "greater")
add("exact_true_with_ties", c(1, 2, 3, 4, 5, 6), c(0, 0, 2, 3, 6, 3), exact = TRUE)

data <- do.call(rbind, lapply(cases, function(c)
  data.frame(case = c$name, i = seq_along(c$x), x = g17(c$x), y = g17(c$y))))
write.csv(data, "samples.csv", row.names = FALSE, quote = FALSE)

golden <- do.call(rbind, lapply(cases, function(c) {
  w <- suppressWarnings(wilcox.test(c$x, c$y, paired = TRUE, alternative = c$alternative,
                                    exact = c$exact, correct = c$correct))
  d <- c$x - c$y
  s <- binom.test(sum(d > 0), sum(d != 0), alternative = c$alternative)
  data.frame(case = c$name, alternative = c$alternative,
             exact = if (is.null(c$exact)) "auto" else if (c$exact) "exact" else "normal",
             correct = as.integer(c$correct),
             exact_used = as.integer(w$method == "Wilcoxon signed rank exact test"),
             V = g17(unname(w$statistic)), p = g17(w$p.value),
             sign_positive = sum(d > 0), sign_n = sum(d != 0), sign_p = g17(s$p.value))
}))
write.csv(golden, "golden.csv", row.names = FALSE, quote = FALSE)
print(golden)
