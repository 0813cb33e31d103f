"""Classify one run of the stability sweep (settling or rising disk).

Prints the csv row rho_s,Ca,status,t_end,v_end,osc,wall_s,end:
- diverged: the run stopped before t = 0.3 on an unstable body: fbmFoam's
  runaway check (the acceleration reversed and grew in each of 4 steps;
  end 'runaway') or a body faster than maxSpeed (end 'maxSpeed'); a run
  that ended because the disk reached a wall (fbmFoam's "reaches the
  domain boundary", no contact model here: end 'wall') is classified by
  its oscillation like a complete one (end 'endTime');
- oscillating: osc >= 0.02, where osc is the rms of the step-to-step
  deviation v_i - (v_(i-1) + v_(i+1))/2 of the vertical velocity over its
  rms, for the last 50 steps (independent of the sign of v: a light disk
  rises, v > 0): the lagged added mass gives a persistent odd-even
  oscillation (5 % at rho_s = 1.25 without stabilisation); a stable run
  only the small noise of cells entering and leaving the body as it moves
  (under 1 % at R/h = 3);
- stable otherwise.
"""
import math
import sys

run, rho, Ca, rc, wall = sys.argv[1:6]
rows = []
for line in open(run + '/postProcessing/fbmBodies/0/particle.dat'):
    if not line.startswith('#'):
        rows.append([float(x) for x in line.split()])
t = [r[0] for r in rows]
v = [r[11] for r in rows]      # Time Fx Fy Fz Tx Ty Tz x y z Ux Uy Uz ...
log = open(run + '/log.fbmFoam').read()
landed = int(rc) == 0 and 'reaches the domain boundary' in log
if 'runs away' in log:
    end = 'runaway'
elif 'exceeds maxSpeed' in log:
    end = 'maxSpeed'
elif landed:
    end = 'wall'
elif int(rc) == 0 and t[-1] >= 0.3 - 1e-9:
    end = 'endTime'
else:
    end = 'error'
if int(rc) != 0 or (t[-1] < 0.3 - 1e-9 and not landed):
    status, osc = 'diverged', float('nan')
else:
    w = v[-50:]
    dev = [w[i] - 0.5*(w[i - 1] + w[i + 1]) for i in range(1, len(w) - 1)]
    rms = lambda x: math.sqrt(sum(y*y for y in x)/max(len(x), 1))
    osc = rms(dev)/max(rms(w), 1e-300)
    status = 'oscillating' if osc >= 0.02 else 'stable'
print('%s,%s,%s,%g,%.6g,%.4g,%s,%s'
      % (rho, Ca, status, t[-1], v[-1], osc, wall, end))
