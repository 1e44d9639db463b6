pp

