#!/usr/bin/python3
"""Independent numpy computations of the expected values in metrics_test.cpp and flip_test.cpp.

Written from the papers' descriptions (Wang et al. 2004 for SSIM; Andersson et al. HPG 2020 /
EG 2021 for FLIP), structured differently from the C++ on purpose: full 2D kernels and direct
windowed sums with np.pad(mode='edge') instead of separable passes, float64 throughout.
Run: python3 tests/ref/metrics_reference.py   (prints the numbers the C++ tests hard-code)
"""
import numpy as np

# ---- test images (the C++ tests build the same ones) ------------------------------------------
def ssim_pair():
    h, w = 14, 16
    t = np.zeros((h, w, 3)); r = np.zeros((h, w, 3))
    for y in range(h):
        for x in range(w):
            t[y, x] = [((x * 7 + y * 3) % 11) / 10, ((x * 2 + y * 5) % 7) / 6, 0.5]
            r[y, x] = [((x * 5 + y * 2) % 9) / 8, ((x * 2 + y * 5) % 7) / 6, 0.25 + 0.05 * (x % 3)]
    return t, r

def flip_pair():
    h, w = 16, 20
    t = np.zeros((h, w, 3)); r = np.zeros((h, w, 3))
    for y in range(h):
        for x in range(w):
            r[y, x] = [0.2, 0.2, 0.2] if x < 10 else [0.8, 0.3, 0.1]
            noise = (((x * 7 + y * 13) % 5) - 2) * 0.03
            base = [0.2, 0.2, 0.2] if x < 11 else [0.8, 0.3, 0.1]
            t[y, x] = [min(max(c + noise, 0.0), 1.0) for c in base]
    return t, r

def hdr_pair():
    h, w = 12, 12
    r = np.zeros((h, w, 3))
    for y in range(h):
        for x in range(w):
            r[y, x] = [0.05 * (x + 1), 0.02 * (y + 1), 8.0 if (x == 6 and y == 6) else 0.1]
    t = r * 1.25
    return t, r

# ---- SSIM ------------------------------------------------------------------------------------
def srgb_encode(l):
    return np.where(l <= 0.0031308, 12.92 * l, 1.055 * np.power(np.maximum(l, 0), 1 / 2.4) - 0.055)

def ssim_map(t, r):
    tt = srgb_encode(np.clip(t, 0, 1)); rr = srgb_encode(np.clip(r, 0, 1))
    i = np.arange(-5, 6)
    g = np.exp(-(i[:, None] ** 2 + i[None, :] ** 2) / (2 * 1.5 ** 2)); g /= g.sum()
    h, w, _ = t.shape
    out = np.zeros((h, w)); valid = np.zeros((h, w), bool)
    c1, c2 = 0.01 ** 2, 0.03 ** 2
    for y in range(5, h - 5):
        for x in range(5, w - 5):
            s = 0
            for c in range(3):
                a = tt[y - 5:y + 6, x - 5:x + 6, c]; b = rr[y - 5:y + 6, x - 5:x + 6, c]
                ma = (g * a).sum(); mb = (g * b).sum()
                va = (g * (a - ma) ** 2).sum(); vb = (g * (b - mb) ** 2).sum(); cab = (g * (a - ma) * (b - mb)).sum()
                s += (2 * ma * mb + c1) * (2 * cab + c2) / ((ma ** 2 + mb ** 2 + c1) * (va + vb + c2))
            out[y, x] = s / 3; valid[y, x] = True
    return out, valid

# ---- FLIP ------------------------------------------------------------------------------------
M = np.array([[10135552 / 24577794, 8788810 / 24577794, 4435075 / 24577794],
              [2613072 / 12288897, 8788810 / 12288897, 887015 / 12288897],
              [1425312 / 73733382, 8788810 / 73733382, 70074185 / 73733382]])
WHITE = M.sum(axis=1)

def conv2(img, k):  # correlation with replicated borders; kernels here are symmetric or handled explicitly
    r = k.shape[0] // 2
    p = np.pad(img, r, mode='edge')
    out = np.zeros_like(img)
    for dy in range(-r, r + 1):
        for dx in range(-r, r + 1):
            out += k[dy + r, dx + r] * p[r + dy:r + dy + img.shape[0], r + dx:r + dx + img.shape[1]]
    return out

def lab_hunt(rgb):
    xyz = rgb @ M.T / WHITE
    d = 6 / 29
    f = np.where(xyz > d ** 3, np.cbrt(xyz), xyz / (3 * d * d) + 4 / 29)
    L = 116 * f[..., 1] - 16
    return np.stack([L, 0.01 * L * 500 * (f[..., 0] - f[..., 1]), 0.01 * L * 200 * (f[..., 1] - f[..., 2])], -1)

def hyab(a, b):
    d = a - b
    return np.abs(d[..., 0]) + np.sqrt(d[..., 1] ** 2 + d[..., 2] ** 2)

def ldr_flip(t, r, ppd):
    def opponent(rgb):
        xyz = rgb @ M.T / WHITE
        return np.stack([116 * xyz[..., 1] - 16, 500 * (xyz[..., 0] - xyz[..., 1]), 200 * (xyz[..., 1] - xyz[..., 2])], -1)
    rad = int(np.ceil(3 * np.sqrt(0.04 / (2 * np.pi ** 2)) * ppd))
    i = np.arange(-rad, rad + 1) / ppd
    z = i[:, None] ** 2 + i[None, :] ** 2
    def csf(terms):
        s = sum(a * np.sqrt(np.pi / b) * np.exp(-np.pi ** 2 * z / b) for a, b in terms)
        return s / s.sum()
    kernels = [csf([(1, 0.0047)]), csf([(1, 0.0053)]), csf([(34.1, 0.04), (13.5, 0.025)])]
    sd = 0.5 * 0.082 * ppd; fr = int(np.ceil(3 * sd))
    xs, ys = np.meshgrid(np.arange(-fr, fr + 1), np.arange(-fr, fr + 1))
    g = np.exp(-(xs ** 2 + ys ** 2) / (2 * sd * sd))
    def signed_normalize(k):
        return np.where(k < 0, k / -k[k < 0].sum(), k / k[k > 0].sum())
    edge = signed_normalize(-xs * g); point = signed_normalize((xs ** 2 / sd ** 2 - 1) * g)
    # conv2 correlates; the edge kernel is odd, so correlation = -convolution. Only norms are used.
    def prepare(img):
        o = opponent(np.clip(img, 0, 1))
        f = np.stack([conv2(o[..., c], kernels[c]) for c in range(3)], -1)
        y = (f[..., 0] + 16) / 116
        xyz = np.stack([(y + f[..., 1] / 500) * WHITE[0], y * WHITE[1], (y - f[..., 2] / 200) * WHITE[2]], -1)
        rgb = np.clip(xyz @ np.linalg.inv(M).T, 0, 1)
        lum = (o[..., 0] + 16) / 116
        e = np.hypot(conv2(lum, edge), conv2(lum, edge.T)); p = np.hypot(conv2(lum, point), conv2(lum, point.T))
        return lab_hunt(rgb), e, p
    lt, et, pt_ = prepare(t); lr, er, pr = prepare(r)
    cmax = hyab(lab_hunt(np.array([0.0, 1, 0])), lab_hunt(np.array([0.0, 0, 1]))) ** 0.7
    e = hyab(lr, lt) ** 0.7
    pc = 0.4 * cmax
    color = np.where(e < pc, 0.95 / pc * e, 0.95 + (e - pc) / (cmax - pc) * 0.05)
    feat = (np.maximum(np.abs(er - et), np.abs(pr - pt_)) / np.sqrt(2)) ** 0.5
    return color ** (1 - feat), cmax

def aces(x):
    k0, k1, k3, k4, k5 = 0.36 * 2.51, 0.6 * 0.03, 0.36 * 2.43, 0.6 * 0.59, 0.14
    return np.clip((k0 * x * x + k1 * x) / (k3 * x * x + k4 * x + k5), 0, 1)

def hdr_flip(t, r, ppd):
    k0, k1, k3, k4, k5 = 0.36 * 2.51, 0.6 * 0.03, 0.36 * 2.43, 0.6 * 0.59, 0.14
    tm = 0.85
    c0 = (k1 - k4 * tm) / (k0 - k3 * tm); c1 = (-k5 * tm) / (k0 - k3 * tm)
    xm = -0.5 * c0 + np.sqrt(0.25 * c0 * c0 - c1)
    Y = r @ np.array([0.2126, 0.7152, 0.0722])
    start = np.log2(xm / Y.max()); stop = np.log2(xm / np.median(Y))
    n = max(2, int(np.ceil(stop - start)))
    best = None
    for k in range(n):
        ex = 2.0 ** (start + k * (stop - start) / (n - 1))
        m, _ = ldr_flip(aces(ex * t), aces(ex * r), ppd)
        best = m if best is None else np.maximum(best, m)
    return best, start, stop, n

if __name__ == '__main__':
    ppd = 0.7 * 3840 / 0.7 * np.pi / 180
    t, r = ssim_pair()
    m, v = ssim_map(t, r)
    print('ssim mean over valid          %.9f (%d pixels)' % (m[v].mean(), v.sum()))
    mask = np.zeros(v.shape, bool); mask[:, :8] = True
    print('ssim mean, columns x < 8       %.9f (%d pixels)' % (m[v & mask].mean(), (v & mask).sum()))
    print('ssim pixel (7, 6)              %.9f' % m[6, 7])
    _, cmax = ldr_flip(np.zeros((1, 1, 3)), np.zeros((1, 1, 3)), ppd)
    print('flip cmax                      %.9f' % cmax)
    t, r = flip_pair()
    f, _ = ldr_flip(t, r, ppd)
    print('ldr flip mean                  %.9f' % f.mean())
    print('ldr flip pixel (10, 8)         %.9f' % f[8, 10])
    print('ldr flip pixel (3, 4)          %.9f' % f[4, 3])
    f, _ = ldr_flip(t, r, 10.0)
    print('ldr flip mean at 10 ppd        %.9f' % f.mean())
    t, r = hdr_pair()
    f, start, stop, n = hdr_flip(t, r, ppd)
    print('hdr flip mean %.9f start %.9f stop %.9f exposures %d' % (f.mean(), start, stop, n))
