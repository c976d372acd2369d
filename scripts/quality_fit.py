# Fit of render.quality's error model on docs/bench-chart.csv (src/quality/calibration.h).
import csv, math, sys
R = {'default': 25.93, 'CesiumMan': 49.47, 'Fox': 43.71, 'RiggedSimple': 39.21}  # projected radius px at 192^2
RREF = 44.0
# The chooser's space only: the averaged operator with every other setting as default (labels
# ending in 'averaged': no 'no-ground-bounce', 'ssaa2', 'static-l1' ... suffix).
chart=list(csv.DictReader(open(sys.argv[1] if len(sys.argv)>1 else 'docs/bench-chart.csv')))
rows=[r for r in chart if r['method']=='proxy' and r['indirect']=='averaged' and r['label'].endswith(' averaged') and r['scene'] in R]
scenes=list(R); orders=[3,4,6]; ups=['bilinear','bilateral']; knots=[1,2,3,4]
def basis(r):
    s=r['scene']; n=int(r['sh_order']); k=int(r['receiver_scale']); up=r['upsampling']
    x=[0.0]*(4+3+8)
    x[scenes.index(s)]=1
    if n!=5: x[4+orders.index(n)]=1
    if k>1:
        t=min(max(math.log2(k*RREF/R[s]),0.0),4.0)
        for j,kn in enumerate(knots):
            w=max(0.0,1-abs(t-kn))
            x[7+ups.index(up)*4+j]+=w
    return x
A=[basis(r) for r in rows]; b=[math.log(float(r['relative_mse'])) for r in rows]
# normal equations, Gauss-Jordan
m=len(A[0]); N=[[sum(a[i]*a[j] for a in A) for j in range(m)] for i in range(m)]; y=[sum(a[i]*bb for a,bb in zip(A,b)) for i in range(m)]
for i in range(m): N[i][i]+=1e-9
for i in range(m):
    p=max(range(i,m),key=lambda r:abs(N[r][i])); N[i],N[p]=N[p],N[i]; y[i],y[p]=y[p],y[i]
    for r in range(m):
        if r!=i:
            f=N[r][i]/N[i][i]
            for c in range(i,m): N[r][c]-=f*N[i][c]
            y[r]-=f*y[i]
c=[y[i]/N[i][i] for i in range(m)]
res=[sum(ai*ci for ai,ci in zip(a,c))-bb for a,bb in zip(A,b)]
print('rows',len(rows),'rms log residual %.4f worst %.4f'%(math.sqrt(sum(r*r for r in res)/len(res)),max(map(abs,res))))
for i,s in enumerate(scenes): print('F',s,'%.5f'%math.exp(c[i]))
print('R(3,4,5,6) = %.4f %.4f 1 %.4f'%tuple(math.exp(c[4+i]) for i in range(3)))
for u in range(2): print('K',ups[u],'x=0..4: 1 '+' '.join('%.4f'%math.exp(c[7+u*4+j]) for j in range(4)))
# F against the rigs' outside_volume_ratio (proxies FitQuality of the fit_version 2 rigs): a line.
OV = {'default': 0.1593, 'CesiumMan': 0.2036, 'Fox': 0.2403, 'RiggedSimple': 0.2122}
F = {s: math.exp(c[i]) for i, s in enumerate(scenes)}
mx = sum(OV.values()) / 4; my = sum(F.values()) / 4
sxx = sum((OV[s] - mx) ** 2 for s in scenes); sxy = sum((OV[s] - mx) * (F[s] - my) for s in scenes)
slope = sxy / sxx; intercept = my - slope * mx
print('floor line: F = %.6f + %.6f x ratio; mean F %.5f; rms %.5f' % (intercept, slope, my,
      math.sqrt(sum((intercept + slope * OV[s] - F[s]) ** 2 for s in scenes) / 4)))
# The chart's ms of each setting on scene 'all' (kChartMs: [order 3..6][k 1, 2, 4, 8][bilinear, bilateral]).
all_rows = {}
for r in chart:
    if r['scene'] == 'all' and r['method'] == 'proxy' and r['indirect'] == 'averaged' and r['label'].endswith(' averaged'):
        all_rows[(int(r['sh_order']), int(r['receiver_scale']), r['upsampling'])] = float(r['ms_per_frame'])
for n in [3, 4, 5, 6]:
    cells = []
    for k in [1, 2, 4, 8]:
        a = all_rows.get((n, k, 'bilinear' if k > 1 else '')); b = all_rows.get((n, k, 'bilateral' if k > 1 else ''))
        cells.append('{%.2f, %.2f}' % (a, b) if a and b else '?')
    print('ms n%d: {%s},' % (n, ', '.join(cells)))
