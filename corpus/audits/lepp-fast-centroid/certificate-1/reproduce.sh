#!/bin/sh
lepp audit --engine fast --method centroid --theta 33 --timeout 5 --inputs corpus/audits/lepp-fast-centroid/certificate-1/input.poly
