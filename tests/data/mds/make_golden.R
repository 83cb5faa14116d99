# Golden values for tests/analysis/stats/test_mds.cpp: a seeded dissimilarity matrix (10 sounds), R's
# stats::cmdscale (classical MDS) and metric SMACOF written out in base R (Guttman transform from
# the cmdscale start, unit weights; de Leeuw 1977) as an independent implementation.
# Run from this folder: Rscript make_golden.R
set.seed(2002)
g17 <- function(x) sprintf("%.17g", x)
n <- 10
labels <- c("wood_plate", "wood_bar", "metal_plate", "metal_bar", "glass_bowl", "glass_plate",
            "porcelain_plate", "plastic_plate", "plastic_bar", "metal_bell")
X <- matrix(rnorm(n * 3), n, 3) %*% diag(c(3, 1.5, 0.6))
D <- as.matrix(dist(X))
noise <- matrix(abs(rnorm(n * n, 0, 0.3)), n)
D <- D + (noise + t(noise)) / 2
diag(D) <- 0
dimnames(D) <- list(labels, labels)
out <- data.frame(sound = labels, apply(D, 2, g17), check.names = FALSE)
write.csv(out, "dissimilarity.csv", row.names = FALSE, quote = FALSE)

cm <- cmdscale(D, k = 2, eig = TRUE)
write.csv(data.frame(sound = labels, dim1 = g17(cm$points[, 1]), dim2 = g17(cm$points[, 2])),
          "classical_points_golden.csv", row.names = FALSE, quote = FALSE)
write.csv(data.frame(eigenvalue = g17(cm$eig)), "classical_eigen_golden.csv", row.names = FALSE, quote = FALSE)

raw_stress <- function(Y) sum((D - as.matrix(dist(Y)))[upper.tri(D)]^2)
Y <- scale(cm$points, scale = FALSE)
s <- raw_stress(Y)
for (it in 1:5000) {
  d <- as.matrix(dist(Y))
  B <- ifelse(d > 0, -D / d, 0)
  diag(B) <- 0
  diag(B) <- -rowSums(B)
  Y <- B %*% Y / n
  s_new <- raw_stress(Y)
  done <- s - s_new <= 1e-13 * s
  s <- s_new
  if (done) break
}
d <- as.matrix(dist(Y))
b <- sum(D * d) / sum(D^2)
stress1 <- sqrt(sum((d - b * D)[upper.tri(D)]^2) / sum(d[upper.tri(d)]^2))
write.csv(data.frame(sound = labels, dim1 = g17(Y[, 1]), dim2 = g17(Y[, 2])), "smacof_points_golden.csv",
          row.names = FALSE, quote = FALSE)
write.csv(data.frame(raw_stress = g17(s), stress1 = g17(stress1), iterations = it), "smacof_stress_golden.csv",
          row.names = FALSE, quote = FALSE)
cat("smacof", it, "iterations, raw stress", s, "stress-1", stress1, "\n")

# Kruskal's nonmetric MDS (MASS::isoMDS, from the cmdscale start); stress is in percent.
iso <- MASS::isoMDS(D, k = 2, maxit = 1000, tol = 1e-10, trace = FALSE)
write.csv(data.frame(stress_percent = g17(iso$stress)), "isomds_golden.csv", row.names = FALSE, quote = FALSE)
