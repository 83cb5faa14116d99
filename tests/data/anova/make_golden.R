# Golden values for tests/analysis/stats/test_rm_anova.cpp: seeded random repeated-measures datasets and
# afex::aov_ez's ANOVA tables (uncorrected, GG, HF; ges and pes) plus car's sphericity diagnostics.
# Run from this folder:  Rscript make_golden.R   (Debian: apt-get install r-cran-afex)
suppressPackageStartupMessages(library(afex))
set.seed(20240519)

g17 <- function(x) sprintf("%.17g", x)

# Subject effects, correlated cell noise (non-spherical: AR(1) over cells with unequal variances)
# and some fixed effects, so that every statistic is non-trivial.
make_data <- function(n_per_group, within_levels, reps = 1) {
  groups <- paste0("g", seq_along(n_per_group))
  cells <- expand.grid(rev(lapply(names(within_levels), function(f)
    paste0(tolower(f), seq_len(within_levels[[f]])))), stringsAsFactors = FALSE)
  cells <- cells[, rev(seq_along(within_levels)), drop = FALSE]
  names(cells) <- names(within_levels)
  nc <- nrow(cells)
  rho <- runif(1, 0.2, 0.8)
  sds <- runif(nc, 0.5, 2.0)
  S <- outer(seq_len(nc), seq_len(nc), function(i, j) rho^abs(i - j)) * outer(sds, sds)
  L <- chol(S)
  fixed <- rnorm(nc, 0, 1)
  rows <- list(); s <- 0
  for (gi in seq_along(groups)) {
    shift <- rnorm(nc, 0, 0.7)
    for (k in seq_len(n_per_group[gi])) {
      s <- s + 1
      subj <- rnorm(1, 0, 2)
      e <- as.vector(rnorm(nc) %*% L)
      for (r in seq_len(reps)) {
        noise <- if (reps > 1) rnorm(nc, 0, 0.5) else 0
        y <- 10 + subj + fixed + shift + e + noise
        rows[[length(rows) + 1]] <- data.frame(subject = sprintf("s%02d", s), group = groups[gi], cells,
                                               rating = y, stringsAsFactors = FALSE)
      }
    }
  }
  d <- do.call(rbind, rows)
  # Shuffle rows: the reader must not depend on order.
  d[sample(nrow(d)), ]
}

datasets <- list(
  w1      = list(n = c(9),       within = list(A = 5)),
  w2      = list(n = c(12),      within = list(A = 3, B = 2)),
  w3      = list(n = c(10),      within = list(A = 3, B = 2, C = 4)),
  w2b     = list(n = c(7, 6),    within = list(A = 4, B = 3)),
  w3b     = list(n = c(5, 4, 6), within = list(A = 2, B = 3, C = 3)),
  w3b_bal = list(n = c(6, 6),    within = list(A = 3, B = 2, C = 2)),
  w2rep   = list(n = c(8),       within = list(A = 3, B = 3), reps = 3),
  w2bb    = list(n = c(9, 8),    within = list(A = 3, B = 2), site = TRUE)
)

for (name in names(datasets)) {
  spec <- datasets[[name]]
  reps <- if (is.null(spec$reps)) 1 else spec$reps
  d <- make_data(spec$n, spec$within, reps)
  within <- names(spec$within)
  between <- if (length(spec$n) > 1) "group" else NULL
  if (is.null(between)) d$group <- NULL
  if (isTRUE(spec$site)) {
    # A second, crossed between factor with unbalanced cells (type III sums of squares matter).
    subjects <- sort(unique(d$subject))
    site <- setNames(rep(c("north", "south"), length.out = length(subjects))[sample(length(subjects))], subjects)
    d$site <- site[d$subject]
    d$rating <- d$rating + ifelse(d$site == "north", 0.8, 0)
    between <- c("group", "site")
  }
  out <- d; out$rating <- g17(out$rating)
  write.csv(out, paste0(name, ".csv"), row.names = FALSE, quote = FALSE)

  fit <- suppressMessages(suppressWarnings(
    aov_ez(id = "subject", dv = "rating", data = d, within = within, between = between,
           fun_aggregate = mean)))
  a0 <- anova(fit, correction = "none", es = c("ges", "pes"))
  agg <- anova(fit, correction = "GG", es = c("ges", "pes"))
  ahf <- suppressWarnings(anova(fit, correction = "HF", es = c("ges", "pes")))
  s <- summary(fit)
  eff <- rownames(a0)
  res <- data.frame(effect = eff, df1 = g17(a0[, "num Df"]), df2 = g17(a0[, "den Df"]),
                    F = g17(a0[, "F"]), p = g17(a0[, "Pr(>F)"]),
                    p_gg = g17(agg[eff, "Pr(>F)"]), df1_gg = g17(agg[eff, "num Df"]),
                    p_hf = g17(ahf[eff, "Pr(>F)"]), df1_hf = g17(ahf[eff, "num Df"]),
                    ges = g17(a0[, "ges"]), pes = g17(a0[, "pes"]),
                    eps_gg = "NA", eps_hf = "NA", mauchly_w = "NA", mauchly_p = "NA",
                    stringsAsFactors = FALSE)
  adj <- s$pval.adjustments
  sph <- s$sphericity.tests
  for (i in seq_along(eff)) {
    if (!is.null(adj) && length(adj) > 0 && eff[i] %in% rownames(adj)) {
      res$eps_gg[i] <- g17(adj[eff[i], "GG eps"])
      res$eps_hf[i] <- g17(adj[eff[i], "HF eps"])
    }
    if (!is.null(sph) && length(sph) > 0 && eff[i] %in% rownames(sph)) {
      res$mauchly_w[i] <- g17(sph[eff[i], "Test statistic"])
      res$mauchly_p[i] <- g17(sph[eff[i], "p-value"])
    }
  }
  write.csv(res, paste0(name, "_golden.csv"), row.names = FALSE, quote = FALSE)
  cat(name, ": ", nrow(d), " rows, ", length(eff), " effects\n", sep = "")
}

# t-tests (R's t.test). Paired: 11 subjects, two conditions, two observations per cell (the mean
# of each subject's cell is compared, as the CLI does). Independent: unequal sizes and variances.
n <- 11
subj <- rnorm(n, 0, 2)
pd <- do.call(rbind, lapply(seq_len(n), function(i) data.frame(
  subject = sprintf("p%02d", i), condition = rep(c("before", "after"), each = 2),
  rating = 50 + subj[i] + rep(c(0, 1.3), each = 2) + rnorm(4, 0, 1.5))))
pd <- pd[sample(nrow(pd)), ]
out <- pd; out$rating <- g17(out$rating)
write.csv(out, "ttest_paired.csv", row.names = FALSE, quote = FALSE)
m <- aggregate(rating ~ subject + condition, data = pd, FUN = mean)
x <- m[m$condition == "before", ]; y <- m[m$condition == "after", ]
x <- x[order(x$subject), ]; y <- y[order(y$subject), ]
tp <- t.test(x$rating, y$rating, paired = TRUE)
id <- data.frame(group = c(rep("recorded", 9), rep("synthesised", 14)),
                 rating = c(rnorm(9, 70, 6), rnorm(14, 64, 14)))
id <- id[sample(nrow(id)), ]
out <- id; out$rating <- g17(out$rating)
write.csv(out, "ttest_independent.csv", row.names = FALSE, quote = FALSE)
g1 <- id$rating[id$group == "recorded"]; g2 <- id$rating[id$group == "synthesised"]
tw <- t.test(g1, g2)
ts <- t.test(g1, g2, var.equal = TRUE)
row <- function(name, t) data.frame(test = name, t = g17(t$statistic), df = g17(t$parameter),
                                    p = g17(t$p.value), ci_low = g17(t$conf.int[1]),
                                    ci_high = g17(t$conf.int[2]))
write.csv(rbind(row("paired_before_after", tp), row("welch_recorded_synthesised", tw),
                row("student_recorded_synthesised", ts)),
          "ttest_golden.csv", row.names = FALSE, quote = FALSE)
cat("afex", as.character(packageVersion("afex")), "car", as.character(packageVersion("car")), "\n")
